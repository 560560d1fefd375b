#pragma once
#include "sluice/high/high.hpp"
// clang-format off
  #  include "sluice/high/one/one.hpp"
