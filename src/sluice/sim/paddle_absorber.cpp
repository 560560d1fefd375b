#include "sluice/sim/paddle_absorber.hpp"

#include <algorithm>

namespace sluice {

PaddleAbsorber::PaddleAbsorber(const io::BodyConfig& paddle, double floor, double gap)
    : paddle_(paddle),
      floor_(floor),
      gap_(gap),
      leak_time_(10 * paddle.prescribed.wavemaker.period) {}

PaddleCorrection PaddleAbsorber::at(double time) const {
  return {displacement_ + velocity_ * (time - since_), velocity_};
}

void PaddleAbsorber::measure(double time, const FluidObservation& fluid) {
  const io::WavemakerConfig& w = paddle_.prescribed.wavemaker;
  displacement_ = at(time).displacement;
  const double since_before = since_;
  since_ = time;
  const double face =
      paddle_.position[0] + 0.5 * paddle_.size[0] + w.signal.displacement(time) + displacement_;
  const Vec3 gauge(face + gap_, paddle_.position[1], 0);
  const double eta = floor_ + fluid.water_height_at(gauge) - w.still_water;
  const double share = std::min(1.0, (time - since_before) / leak_time_);
  mean_ = read_ ? mean_ + share * (eta - mean_) : eta;
  read_ = true;
  velocity_ =
      w.absorption_gain * (w.signal.elevation(time) - (eta - mean_)) - displacement_ / leak_time_;
}

}  // namespace sluice
