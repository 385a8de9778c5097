// editor/places.cpp — the city list (see places.hpp). Coordinates of the
// city centre to 0.01 deg; offsets of standard time.
#include "places.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace aerial::editor {
namespace {

constexpr std::array kPlaces{
    Place{"Honolulu", 21.31, -157.86, -10.0},
    Place{"Anchorage", 61.22, -149.90, -9.0},
    Place{"Vancouver", 49.28, -123.12, -8.0},
    Place{"San Francisco", 37.77, -122.42, -8.0},
    Place{"Los Angeles", 34.05, -118.24, -8.0},
    Place{"Death Valley", 36.46, -116.87, -8.0},
    Place{"Denver", 39.74, -104.99, -7.0},
    Place{"Mexico City", 19.43, -99.13, -6.0},
    Place{"Chicago", 41.88, -87.63, -6.0},
    Place{"Havana", 23.11, -82.37, -5.0},
    Place{"Lima", -12.05, -77.04, -5.0},
    Place{"Bogota", 4.71, -74.07, -5.0},
    Place{"New York", 40.71, -74.01, -5.0},
    Place{"Ushuaia", -54.80, -68.30, -3.0},
    Place{"Buenos Aires", -34.60, -58.38, -3.0},
    Place{"Rio de Janeiro", -22.91, -43.17, -3.0},
    Place{"Reykjavik", 64.15, -21.94, 0.0},
    Place{"Madrid", 40.42, -3.70, 1.0},
    Place{"London", 51.51, -0.13, 0.0},
    Place{"Paris", 48.86, 2.35, 1.0},
    Place{"Tamanrasset (Sahara)", 22.79, 5.53, 1.0},
    Place{"Oslo", 59.91, 10.75, 1.0},
    Place{"Rome", 41.90, 12.50, 1.0},
    Place{"Berlin", 52.52, 13.40, 1.0},
    Place{"Longyearbyen (Svalbard)", 78.22, 15.65, 1.0},
    Place{"Stockholm", 59.33, 18.07, 1.0},
    Place{"Cape Town", -33.92, 18.42, 2.0},
    Place{"Athens", 37.98, 23.73, 2.0},
    Place{"Helsinki", 60.17, 24.94, 2.0},
    Place{"Istanbul", 41.01, 28.98, 3.0},
    Place{"Cairo", 30.04, 31.24, 2.0},
    Place{"Nairobi", -1.29, 36.82, 3.0},
    Place{"Moscow", 55.76, 37.62, 3.0},
    Place{"Dubai", 25.20, 55.27, 4.0},
    Place{"Mumbai", 19.08, 72.88, 5.5},
    Place{"Kathmandu", 27.72, 85.32, 5.75},
    Place{"Singapore", 1.35, 103.82, 8.0},
    Place{"Hong Kong", 22.32, 114.17, 8.0},
    Place{"Beijing", 39.90, 116.41, 8.0},
    Place{"Seoul", 37.57, 126.98, 9.0},
    Place{"Tokyo", 35.68, 139.69, 9.0},
    Place{"Sydney", -33.87, 151.21, 10.0},
    Place{"McMurdo Station (Antarctica)", -77.85, 166.67, 12.0},
    Place{"Auckland", -36.85, 174.76, 12.0},
};

char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

}  // namespace

std::span<const Place> places() { return kPlaces; }

const Place* findPlace(std::string_view name) {
    for (const Place& p : kPlaces)
        if (std::ranges::equal(p.name, name, [](char a, char b) { return lower(a) == lower(b); })) return &p;
    return nullptr;
}

void applyPlace(Location& where, const Place& place) {
    where.latitudeDeg = place.latitudeDeg;
    where.longitudeDeg = place.longitudeDeg;
    where.utcOffsetHours = place.utcOffsetHours;
}

}  // namespace aerial::editor
