// What drives a structure in time: the factor of a load pattern that follows a time series,
// and a base acceleration sampled from a record (engine/model/dynamics_spec.hpp).
#pragma once

#include "model/dynamics_spec.hpp"

namespace plastica {

// The series' factor at time t.
double series_value(const TimeSeriesSpec& series, double t);
// The record's acceleration at time t: linear between samples (the first at t = 0), zero after.
double ground_acceleration(const GroundMotionSpec& motion, double t);

} // namespace plastica
