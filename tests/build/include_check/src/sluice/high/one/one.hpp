#pragma once
#include "sluice/high/high.hpp"
#include "sluice/low/low.hpp"
