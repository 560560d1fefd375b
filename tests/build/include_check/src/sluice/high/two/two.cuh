#pragma once
#include "sluice/high/high.hpp"
  #  include "sluice/high/one/one.hpp"
