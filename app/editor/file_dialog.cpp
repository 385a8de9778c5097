// editor/file_dialog.cpp — see file_dialog.hpp.
#include "file_dialog.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace aerial::editor {
namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> extensions,
                      const std::string& start) {
    title_ = std::move(title);
    mode_ = mode;
    extensions_ = std::move(extensions);
    std::error_code ec;
    fs::path startPath = start.empty() ? fs::current_path(ec) : fs::absolute(start, ec);
    if (fs::is_directory(startPath, ec)) {
        directory_ = startPath.string();
        entry_ = mode == Mode::Directory ? directory_ : (fs::path(directory_) / "").string();
    } else {
        directory_ = startPath.parent_path().string();
        entry_ = startPath.string();
        if (!fs::is_directory(directory_, ec)) directory_ = fs::current_path(ec).string();
    }
    error_.clear();
    result_.clear();
    list();
    visible_ = openRequested_ = true;
}

void FileDialog::list() {
    items_.clear();
    std::error_code ec;
    for (const fs::directory_entry& e :
         fs::directory_iterator(directory_, fs::directory_options::skip_permission_denied, ec)) {
        const std::string name = e.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code ec2;
        const bool dir = e.is_directory(ec2);
        if (!dir) {
            if (mode_ == Mode::Directory) continue;
            const std::string ext = lower(e.path().extension().string());
            if (!extensions_.empty() &&
                std::find(extensions_.begin(), extensions_.end(), ext) == extensions_.end())
                continue;
        }
        items_.push_back({name, dir});
    }
    std::sort(items_.begin(), items_.end(), [](const Item& a, const Item& b) {
        if (a.directory != b.directory) return a.directory;
        return a.name < b.name;
    });
}

bool FileDialog::accept(const std::string& path) {
    std::error_code ec;
    fs::path p(path);
    if (p.empty()) return false;
    if (mode_ == Mode::Directory) {
        result_ = fs::absolute(p, ec).lexically_normal().string();
        return true;
    }
    if (fs::is_directory(p, ec)) {
        directory_ = fs::absolute(p, ec).lexically_normal().string();
        entry_ = (fs::path(directory_) / "").string();
        list();
        return false;
    }
    if (mode_ == Mode::Open && !fs::exists(p, ec)) {
        error_ = "No such file: " + p.string();
        return false;
    }
    if (mode_ == Mode::Save) {
        const std::string ext = lower(p.extension().string());
        if (!extensions_.empty() &&
            std::find(extensions_.begin(), extensions_.end(), ext) == extensions_.end())
            p += extensions_.front();
        if (!fs::is_directory(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec)) {
            error_ = "No such folder: " + p.parent_path().string();
            return false;
        }
    }
    result_ = fs::absolute(p, ec).lexically_normal().string();
    return true;
}

bool FileDialog::submit(const std::string& path) {
    if (!visible_) return false;
    submitted_ = accept(path);
    return submitted_;
}

bool FileDialog::draw() {
    if (!visible_) return false;
    if (openRequested_) {
        ImGui::OpenPopup(title_.c_str());
        openRequested_ = false;
    }
    if (submitted_) {
        submitted_ = false;
        visible_ = false;
        if (ImGui::BeginPopupModal(title_.c_str())) {
            ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
        }
        return true;
    }
    bool confirmed = false;
    const ImVec2 size(std::min(640.0f, ImGui::GetIO().DisplaySize.x - 40.0f),
                      std::min(440.0f, ImGui::GetIO().DisplaySize.y - 40.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal(title_.c_str(), &visible_)) {
        if (ImGui::Button("Up")) {
            fs::path parent = fs::path(directory_).parent_path();
            if (!parent.empty()) {
                directory_ = parent.string();
                if (mode_ == Mode::Directory) entry_ = directory_;
                list();
            }
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(directory_.c_str());
        std::string filter;
        for (const std::string& e : extensions_) {
            if (!filter.empty()) filter += ' ';
            filter += '*';
            filter += e;
        }
        if (!filter.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("(%s)", filter.c_str());
        }
        const float footer =
            ImGui::GetFrameHeightWithSpacing() * 2.0f + ImGui::GetTextLineHeightWithSpacing();
        ImGui::BeginChild("##files", ImVec2(0, -footer), true);
        std::string enter;
        for (const Item& item : items_) {
            const std::string label = item.directory ? item.name + "/" : item.name;
            const std::string full = (fs::path(directory_) / item.name).string();
            if (ImGui::Selectable(label.c_str(), entry_ == full, ImGuiSelectableFlags_AllowDoubleClick)) {
                if (item.directory && ImGui::IsMouseDoubleClicked(0))
                    enter = full;
                else if (!item.directory || mode_ == Mode::Directory)
                    entry_ = full;
                if (!item.directory && ImGui::IsMouseDoubleClicked(0) && accept(full)) confirmed = true;
            }
        }
        ImGui::EndChild();
        if (!enter.empty()) {
            directory_ = enter;
            if (mode_ == Mode::Directory) entry_ = enter;
            list();
        }
        ImGui::SetNextItemWidth(-1.0f);
        if (ImGui::InputText("##path", &entry_, ImGuiInputTextFlags_EnterReturnsTrue) && accept(entry_))
            confirmed = true;
        if (!error_.empty())
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", error_.c_str());
        else
            ImGui::TextDisabled("Type a path or pick one above");
        const char* okLabel = mode_ == Mode::Save ? "Save" : mode_ == Mode::Directory ? "Choose" : "Open";
        if (ImGui::Button(okLabel, ImVec2(100, 0)) && accept(entry_)) confirmed = true;
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0))) visible_ = false;
        if (confirmed) visible_ = false;
        if (!visible_) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    } else {
        visible_ = false;
    }
    return confirmed;
}

}  // namespace aerial::editor
