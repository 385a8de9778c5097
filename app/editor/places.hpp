// editor/places.hpp — a short list of cities an artist can pick instead of
// typing latitude, longitude and UTC offset (issue: "a city list is a
// nicety, lat/long the must"). Standard (winter) time offsets: daylight
// saving is the artist's choice, one hour more on the UTC offset.
#pragma once

#include <aerial/sun.hpp>

#include <span>
#include <string_view>

namespace aerial::editor {

struct Place {
    std::string_view name;
    double latitudeDeg;     ///< north positive
    double longitudeDeg;    ///< east positive
    double utcOffsetHours;  ///< standard time
};

/// Every place, sorted by longitude from west to east (as a time-zone map reads).
std::span<const Place> places();

/// The place of that name (ASCII case-insensitive), or nullptr.
const Place* findPlace(std::string_view name);

/// Sets the location's latitude, longitude and UTC offset; date, time mode,
/// north offset and the undated fields are left as they are.
void applyPlace(Location& where, const Place& place);

}  // namespace aerial::editor
