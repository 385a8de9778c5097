// clock.cpp — parsing and formatting times of day (aerial/clock.hpp).
#include <aerial/clock.hpp>
#include <aerial/timeline.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aerial {
namespace {

std::string_view trim(std::string_view text) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!text.empty() && space(text.front())) text.remove_prefix(1);
    while (!text.empty() && space(text.back())) text.remove_suffix(1);
    return text;
}

/// 1..maxDigits decimal digits.
bool parseDigits(std::string_view text, std::size_t maxDigits, int& out) {
    if (text.empty() || text.size() > maxDigits) return false;
    out = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        out = out * 10 + (c - '0');
    }
    return true;
}

bool parseHours(std::string_view text, double& hours) {
    if (text.size() > 1 && (text.back() == 'h' || text.back() == 'H'))
        text = trim(text.substr(0, text.size() - 1));
    if (text.empty() || text.size() > 64) return false;
    for (char c : text)
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
            return false;
    const std::string copy(text);
    char* end = nullptr;
    const double value = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size() || !std::isfinite(value) || value < 0.0 || value >= 24.0)
        return false;
    hours = value;
    return true;
}

}  // namespace

bool parseClock(std::string_view text, double& hours) {
    text = trim(text);
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) return parseHours(text, hours);
    const std::string_view hh = text.substr(0, colon);
    std::string_view rest = text.substr(colon + 1);
    const std::size_t colon2 = rest.find(':');
    const std::string_view mm = rest.substr(0, colon2);
    const std::string_view ss =
        colon2 == std::string_view::npos ? std::string_view() : rest.substr(colon2 + 1);
    int h = 0, m = 0, s = 0;
    if (!parseDigits(hh, 2, h) || mm.size() != 2 || !parseDigits(mm, 2, m)) return false;
    if (colon2 != std::string_view::npos && (ss.size() != 2 || !parseDigits(ss, 2, s))) return false;
    if (h > 23 || m > 59 || s > 59) return false;
    hours = h + m / 60.0 + s / 3600.0;
    return true;
}

std::string formatClock(double hours, ClockResolution resolution) {
    const double t = wrapHours(hours);
    char text[16];
    if (resolution == ClockResolution::Minutes) {
        const int minutes = int(std::floor(t * 60.0 + 1e-6));
        std::snprintf(text, sizeof text, "%02d:%02d", (minutes / 60) % 24, minutes % 60);
        return text;
    }
    const long long seconds = std::llround(t * 3600.0) % 86400;
    if (seconds % 60 == 0)
        std::snprintf(text, sizeof text, "%02lld:%02lld", seconds / 3600, seconds / 60 % 60);
    else
        std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld", seconds / 3600, seconds / 60 % 60,
                      seconds % 60);
    return text;
}

}  // namespace aerial
