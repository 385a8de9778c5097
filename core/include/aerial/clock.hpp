// aerial/clock.hpp — times of day as people write them ("06:30", "18:45:30",
// "7.5h"): the one parser and formatter of the CLI, the editor and its
// scripts.
//
// Usage:
//   double t = 0.0;
//   if (!aerial::parseClock("06:30", t)) complain();         // t = 6.5
//   std::string a = aerial::formatClock(18.7525);           // "18:45:09"
//   std::string b = aerial::formatClock(18.7525, aerial::ClockResolution::Minutes);  // "18:45"
#pragma once

#include <string>
#include <string_view>

namespace aerial {

/// Parses a time of day [h]: "H:MM", "HH:MM" or "HH:MM:SS" (HH 0..23, MM and
/// SS two digits 00..59), or decimal hours in [0, 24) with an optional "h"
/// suffix ("7.5", "7.5h"); spaces around are ignored. No "nan", "inf" or hex
/// floats. Returns false (and leaves `hours` alone) on anything else.
bool parseClock(std::string_view text, double& hours);

enum class ClockResolution {
    Seconds,  ///< rounded to the second: "HH:MM", or "HH:MM:SS" off the minute
    Minutes,  ///< the minute that has begun (as a clock shows it): "HH:MM"
};

/// A time [h], wrapped into [0, 24) first (wrapHours), as text.
std::string formatClock(double hours, ClockResolution resolution = ClockResolution::Seconds);

}  // namespace aerial
