// editor/file_dialog.hpp — a small ImGui file dialog (modal): the current
// directory's folders and the files matching the filter, a path entry, Up,
// OK and Cancel. Open, Save (a file name that may not exist yet) and
// Directory (Export for game) modes.
//
// Usage:
//   dialog.open("Open preset", FileDialog::Mode::Open, {".json"}, startDirectory);
//   if (dialog.draw()) openPreset(dialog.result());   // every frame
#pragma once

#include <string>
#include <vector>

namespace aerial::editor {

class FileDialog {
public:
    enum class Mode { Open, Save, Directory };

    /// Shows the dialog from the next draw(). `extensions` (lower case, with
    /// the dot) filter the listing; the first is appended to a saved name
    /// without one of them. `start` is a directory or a file in one.
    void open(std::string title, Mode mode, std::vector<std::string> extensions, const std::string& start);
    /// Draws the dialog when open; true on the frame the user confirms.
    bool draw();
    bool isOpen() const { return visible_; }
    /// Automation: `path` as if typed into the entry and confirmed; the next
    /// draw() then returns true. False when the dialog is not open or would
    /// refuse the path (see error()).
    bool submit(const std::string& path);
    const std::string& error() const { return error_; }
    /// The confirmed path.
    const std::string& result() const { return result_; }

private:
    void list();
    bool accept(const std::string& path);

    std::string title_;
    Mode mode_ = Mode::Open;
    std::vector<std::string> extensions_;
    std::string directory_;
    std::string entry_;  // the path entry
    std::string result_;
    std::string error_;
    struct Item {
        std::string name;
        bool directory = false;
    };
    std::vector<Item> items_;
    bool visible_ = false;
    bool openRequested_ = false;
    bool submitted_ = false;
};

}  // namespace aerial::editor
