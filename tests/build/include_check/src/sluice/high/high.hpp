#pragma once
#include "sluice/low/low.hpp"
