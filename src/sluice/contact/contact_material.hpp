// What a body's surface is made of, as the penalty contact law (hertz_mindlin.hpp) reads it.
#pragma once

namespace sluice {

struct ContactMaterial {
  double young = 1e7;        // E [Pa]
  double poisson = 0.3;      // nu
  double restitution = 0.5;  // e in (0, 1]
  double friction = 0.5;     // Coulomb mu >= 0
};

}  // namespace sluice
