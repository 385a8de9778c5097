// editor/settings.hpp — what the editor remembers between runs, apart from
// presets: recent files and the session (camera, view settings). Stored as
// JSON in configDirectory(). No GUI.
#pragma once

#include <string>
#include <vector>

namespace aerial::editor {

/// $AERIAL_CONFIG_DIR if set, else $XDG_CONFIG_HOME/aerial, else
/// $HOME/.config/aerial (else /tmp/aerial-config).
std::string configDirectory();

/// Most recently used files, newest first, at most kMaxRecentFiles.
class RecentFiles {
public:
    static constexpr std::size_t kMaxRecentFiles = 10;
    explicit RecentFiles(std::string file);  ///< e.g. configDirectory() + "/recent.json"
    void load();
    /// Adds (or moves) `path` to the front (made absolute) and saves.
    void add(const std::string& path);
    void remove(const std::string& path);
    void clear();
    const std::vector<std::string>& files() const { return files_; }

private:
    void save() const;
    std::string file_;
    std::vector<std::string> files_;
};

/// The editor session: the viewport camera and the view settings (never in
/// the preset).
struct Session {
    std::string cameraJson;  ///< viewport/camera_controller.hpp's cameraStateToJson; "" = default
    std::string display;     ///< OCIO display ("" = default)
    std::string view;        ///< OCIO view ("" = default)
    double exposureEv = 0.0;
    double resolutionScale = 0.5;
    double timeHours = 9.0;
    /// The window's layout: panels shown, their sizes [px] (0: default),
    /// Maximize viewport and Game view.
    bool showOutliner = true, showInspector = true, showTimeline = true;
    double outlinerWidth = 0.0, inspectorWidth = 0.0, timelineHeight = 0.0;
    bool maximized = false, gameView = false;
    bool outlinerCollapsed = false, inspectorCollapsed = false, timelineCollapsed = false;
    /// The getting-started sheet (F1) has been shown once: the first start
    /// opens it by itself, later ones do not.
    bool helpSeen = false;
    /// The curves shown in the timeline's curve view (curve_view.hpp's curveKey).
    std::vector<std::string> curves;
    /// The step dragged keys snap to [min] (the curve view's Snap: 1, 5, 15, 60).
    double snapMinutes = 15.0;

    /// Reads `file`; missing or malformed fields keep their values.
    void load(const std::string& file);
    /// Writes `file` (aside, then renamed). False on failure.
    bool save(const std::string& file) const;
};

}  // namespace aerial::editor
