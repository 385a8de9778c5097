// editor/settings.cpp — see settings.hpp.
#include "settings.hpp"
#include "user_dirs.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace aerial::editor {
namespace fs = std::filesystem;

std::string configDirectory() {
    return userDirectory({"AERIAL_CONFIG_DIR", "XDG_CONFIG_HOME", ".config", "/tmp/aerial-config"});
}

namespace {

nlohmann::json readJson(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return nlohmann::json();
    std::ostringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str(), nullptr, false);
}

bool writeText(const std::string& file, const std::string& text) {
    std::error_code ec;
    fs::create_directories(fs::path(file).parent_path(), ec);
    const std::string temp = file + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) return false;
    }
    fs::rename(temp, file, ec);
    return !ec;
}

}  // namespace

RecentFiles::RecentFiles(std::string file) : file_(std::move(file)) {}

void RecentFiles::load() {
    files_.clear();
    const nlohmann::json json = readJson(file_);
    if (!json.is_object() || !json.contains("files") || !json["files"].is_array()) return;
    for (const nlohmann::json& f : json["files"])
        if (f.is_string() && files_.size() < kMaxRecentFiles) files_.push_back(f.get<std::string>());
}

void RecentFiles::add(const std::string& path) {
    std::error_code ec;
    std::string absolute = fs::absolute(path, ec).lexically_normal().string();
    if (ec) absolute = path;
    files_.erase(std::remove(files_.begin(), files_.end(), absolute), files_.end());
    files_.insert(files_.begin(), absolute);
    if (files_.size() > kMaxRecentFiles) files_.resize(kMaxRecentFiles);
    save();
}

void RecentFiles::remove(const std::string& path) {
    files_.erase(std::remove(files_.begin(), files_.end(), path), files_.end());
    save();
}

void RecentFiles::clear() {
    files_.clear();
    save();
}

void RecentFiles::save() const {
    nlohmann::json json = {{"files", files_}};
    writeText(file_, json.dump(2) + "\n");
}

void Session::load(const std::string& file) {
    const nlohmann::json json = readJson(file);
    if (!json.is_object()) return;
    auto number = [&](const char* key, double& out, double lo, double hi) {
        if (json.contains(key) && json[key].is_number()) {
            const double v = json[key].get<double>();
            if (std::isfinite(v)) out = std::clamp(v, lo, hi);
        }
    };
    auto text = [&](const char* key, std::string& out) {
        if (json.contains(key) && json[key].is_string()) out = json[key].get<std::string>();
    };
    if (json.contains("camera") && json["camera"].is_object()) cameraJson = json["camera"].dump();
    text("display", display);
    text("view", view);
    number("exposure_ev", exposureEv, -30.0, 30.0);
    number("resolution_scale", resolutionScale, 0.125, 1.0);
    number("time_h", timeHours, 0.0, 23.999);
    number("snap_min", snapMinutes, 1.0, 60.0);
    if (json.contains("curves") && json["curves"].is_array()) {
        curves.clear();
        for (const nlohmann::json& c : json["curves"])
            if (c.is_string()) curves.push_back(c.get<std::string>());
    }
    if (json.contains("layout") && json["layout"].is_object()) {
        const nlohmann::json& layout = json["layout"];
        auto flag = [&](const char* key, bool& out) {
            if (layout.contains(key) && layout[key].is_boolean()) out = layout[key].get<bool>();
        };
        auto size = [&](const char* key, double& out) {
            if (layout.contains(key) && layout[key].is_number()) {
                const double v = layout[key].get<double>();
                if (std::isfinite(v)) out = std::clamp(v, 0.0, 10000.0);
            }
        };
        flag("outliner", showOutliner);
        flag("inspector", showInspector);
        flag("timeline", showTimeline);
        flag("maximized", maximized);
        flag("game_view", gameView);
        flag("help_seen", helpSeen);
        flag("outliner_collapsed", outlinerCollapsed);
        flag("inspector_collapsed", inspectorCollapsed);
        flag("timeline_collapsed", timelineCollapsed);
        size("outliner_width", outlinerWidth);
        size("inspector_width", inspectorWidth);
        size("timeline_height", timelineHeight);
    }
}

bool Session::save(const std::string& file) const {
    nlohmann::json json = {{"display", display},
                           {"view", view},
                           {"exposure_ev", exposureEv},
                           {"resolution_scale", resolutionScale},
                           {"time_h", timeHours},
                           {"curves", curves},
                           {"snap_min", snapMinutes},
                           {"layout",
                            {{"outliner", showOutliner},
                             {"inspector", showInspector},
                             {"timeline", showTimeline},
                             {"maximized", maximized},
                             {"game_view", gameView},
                             {"help_seen", helpSeen},
                             {"outliner_collapsed", outlinerCollapsed},
                             {"inspector_collapsed", inspectorCollapsed},
                             {"timeline_collapsed", timelineCollapsed},
                             {"outliner_width", outlinerWidth},
                             {"inspector_width", inspectorWidth},
                             {"timeline_height", timelineHeight}}}};
    if (!cameraJson.empty()) {
        nlohmann::json camera = nlohmann::json::parse(cameraJson, nullptr, false);
        if (camera.is_object()) json["camera"] = camera;
    }
    return writeText(file, json.dump(2) + "\n");
}

}  // namespace aerial::editor
