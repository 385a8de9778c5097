// editor/editor_files.cpp — files and safety: New, Open (dialog, recent,
// drag and drop), Save / Save As, Load scene (glTF), the unsaved-changes
// prompt (Save / Discard / Cancel) before anything that would lose work, the
// load-error modal (the loader's errors, file:line:col: /pointer: reason; the
// document is left as it was), crash recovery and Export for game. Uses the
// Document, the Dialogs part and the EditState (a new document selects the
// global fog).
#include "editor.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <aerial/renderer/gltf.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace aerial::editor {
namespace fs = std::filesystem;

namespace {

/// The CLI's validate format: "file:line:col: /pointer: reason".
std::string issueText(const PresetIssue& issue) {
    std::string text = issue.file;
    if (issue.line > 0) {
        text += ':';
        text += std::to_string(issue.line);
        text += ':';
        text += std::to_string(issue.column);
    }
    text += ": ";
    if (issue.severity == PresetIssue::Severity::Warning) text += "warning: ";
    if (!issue.pointer.empty()) {
        text += issue.pointer;
        text += ": ";
    }
    text += issue.message;
    return text;
}

std::string lowerExtension(const std::string& path) {
    std::string e = fs::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

}  // namespace

void Editor::askUnsaved(Pending action, std::string path) {
    dialogs_.pending = action;
    dialogs_.pendingPath = std::move(path);
    if (doc_.dirty())
        dialogs_.openUnsavedModal = true;
    else
        runPending();
}

void Editor::requestNew() { askUnsaved(Pending::New, {}); }

void Editor::requestOpen(const std::string& path) {
    if (path.empty()) {
        dialogs_.purpose = DialogPurpose::Open;
        dialogs_.fileDialog.open(
            "Open preset", FileDialog::Mode::Open, {".json"},
            doc_.path().empty() ? std::string() : fs::path(doc_.path()).parent_path().string());
        return;
    }
    // A file that cannot be loaded is said at once: no save-or-discard
    // question about the current work first.
    const PresetLoadResult probe = loadPreset(path);
    if (!probe.ok()) {
        reportLoadFailure(path, probe);
        return;
    }
    askUnsaved(Pending::Open, path);
}

void Editor::reportLoadFailure(const std::string& path, const PresetLoadResult& result) {
    std::string text;
    for (const PresetIssue& e : result.errors) text += issueText(e) + "\n";
    if (result.errors.empty()) text = path + ": cannot be loaded\n";
    showError("Cannot open " + path + " (nothing was changed):", text);
    std::error_code ec;
    if (!fs::exists(path, ec)) recent_.remove(fs::absolute(path, ec).lexically_normal().string());
}

void Editor::requestQuit() { askUnsaved(Pending::Quit, {}); }

void Editor::runPending() {
    const Pending action = dialogs_.pending;
    dialogs_.pending = Pending::None;
    dialogs_.continueAfterSave = false;
    switch (action) {
        case Pending::None:
        case Pending::OpenRecovery:
            break;
        case Pending::New:
            doc_.reset(defaultPreset());
            select({Selection::Kind::Fog, -1});
            edit_.selectedParam.reset();
            edit_.selectedKey = -1;
            edit_.curves.resetRanges();
            setStatus("New preset (the built-in default)");
            break;
        case Pending::Open:
            openPreset(dialogs_.pendingPath);
            break;
        case Pending::Quit:
            quit_ = true;
            break;
    }
}

bool Editor::openPreset(const std::string& path) {
    const PresetLoadResult result = doc_.open(path);
    if (!result.ok()) {
        reportLoadFailure(path, result);
        return false;
    }
    recent_.add(path);
    select({Selection::Kind::Fog, -1});
    edit_.selectedParam.reset();
    edit_.selectedKey = -1;
    edit_.curves.resetRanges();  // another preset's curves: their ranges follow their keys
    goToPresetView();            // a preset with a view opens where it is meant to be seen from
    std::string status = "Opened " + path;
    if (!result.warnings.empty()) {
        status += " (";
        status += std::to_string(result.warnings.size());
        status += " warnings: ";
        status += issueText(result.warnings.front());
        status += ")";
    }
    setStatus(status);
    return true;
}

bool Editor::savePresetTo(const std::string& path) {
    // Save As: a preset never named by the artist takes the new file's name.
    std::string renamed;
    if (path != doc_.path()) {
        renamed = nameAfterSaveAs(doc_.preset().name, doc_.path(), path);
        if (!renamed.empty()) doc_.apply("Rename preset", "", [&](Preset& p) { p.name = renamed; });
        rebaseMeshesForSave(path);
    }
    const SaveResult result = doc_.save(path);
    if (!result.ok()) {
        std::string text;
        for (const PresetIssue& e : result.errors) text += issueText(e) + "\n";
        showError("Cannot save " + path + ":", text);
        return false;
    }
    recent_.add(path);
    setStatus("Saved " + path + (renamed.empty() ? std::string() : " as \"" + renamed + "\"") +
              (edit_.pending.empty() ? std::string()
                                     : " (" + std::to_string(edit_.pending.size()) +
                                           " unkeyed change(s) not in it: Key or Revert them)"));
    return true;
}

void Editor::saveOrSaveAs(bool forceDialog) {
    if (!forceDialog && !doc_.path().empty()) {
        savePresetTo(doc_.path());
        return;
    }
    dialogs_.purpose = DialogPurpose::SaveAs;
    std::string start = doc_.path();
    if (start.empty()) start = (fs::current_path() / "untitled.json").string();
    dialogs_.fileDialog.open("Save preset as", FileDialog::Mode::Save, {".json"}, start);
}

bool Editor::loadScene(const std::string& path) {
    renderer::GltfLoadResult loaded = renderer::loadGltfScene(path);
    if (!loaded.ok()) {
        showError("Cannot load the scene " + path + ":", loaded.error);
        return false;
    }
    setScene(loaded.scene);
    view_.resetCloudHistory = true;
    view_.scenePath = path;
    // Frame the scene: the bounds of every vertex in world space.
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const renderer::SceneMesh& mesh : loaded.scene.meshes)
        for (const glm::vec3& p : mesh.positions) {
            const glm::dvec3 w = glm::dvec3(mesh.worldFromObject * glm::dvec4(glm::dvec3(p), 1.0));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    if (hi.x >= lo.x && view_.size.y > 0.0)
        view_.camera.frame((lo + hi) * 0.5, std::max(0.5 * glm::length(hi - lo), 0.5),
                           view_.size.x / view_.size.y);
    std::string status = "Loaded scene " + path;
    if (!loaded.warnings.empty()) {
        status += " (";
        status += loaded.warnings.front();
        status += ")";
    }
    setStatus(status);
    return true;
}

void Editor::handleDrops() {
    std::vector<Dialogs::Drop> drops;
    drops.swap(dialogs_.drops);
    for (const auto& [path, asMesh] : drops) {
        const std::string ext = lowerExtension(path);
        if (ext == ".json")
            requestOpen(path);
        else if ((ext == ".gltf" || ext == ".glb") && asMesh)
            addMeshVolumeFromFile(path);  // Shift+drop: a mesh fog volume
        else if ((ext == ".gltf" || ext == ".glb") && loadScene(path))
            setStatus(status_ + " (Shift+drop adds a glTF as a mesh fog volume instead)");
        else if (ext == ".gltf" || ext == ".glb")
            ;  // loadScene said why it could not
        else
            setStatus("Cannot open " + path + ": drop a preset (.json) or a glTF scene (.gltf, .glb)");
    }
}

void Editor::drawFileDialogs() {
    const bool wasOpen = dialogs_.fileDialog.isOpen();
    if (dialogs_.fileDialog.draw()) {
        const std::string path = dialogs_.fileDialog.result();
        switch (dialogs_.purpose) {
            case DialogPurpose::Open:
                requestOpen(path);
                break;
            case DialogPurpose::SaveAs:
                if (savePresetTo(path) && dialogs_.continueAfterSave) runPending();
                break;
            case DialogPurpose::Scene:
                loadScene(path);
                break;
            case DialogPurpose::Screenshot: {
                std::string error;
                if (screenshot(path, error))
                    setStatus("Screenshot " + path);
                else
                    showError("Cannot write the screenshot:", error);
                break;
            }
            case DialogPurpose::Export:
                startExport(path);
                break;
            case DialogPurpose::Mesh:
                if (dialogs_.meshVolumeIndex < 0)
                    addMeshVolumeFromFile(path);
                else
                    setVolumeMesh(dialogs_.meshVolumeIndex, path);
                break;
            case DialogPurpose::None:
                break;
        }
        dialogs_.purpose = DialogPurpose::None;
    } else if (wasOpen && !dialogs_.fileDialog.isOpen()) {
        // Cancelled: a Save As from the unsaved-changes prompt cancels what it guarded.
        if (dialogs_.continueAfterSave) {
            dialogs_.continueAfterSave = false;
            dialogs_.pending = Pending::None;
        }
        dialogs_.purpose = DialogPurpose::None;
    }
    if (export_.done()) {
        if (export_.succeeded())
            setStatus(exportedStatus());
        else
            showError("Export for game failed:", export_.summary());
        export_.acknowledge();
    }
}

void Editor::drawModals() {
    if (dialogs_.openErrorModal) {
        ImGui::OpenPopup("Error##modal");
        dialogs_.openErrorModal = false;
    }
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, ImGui::GetIO().DisplaySize.x - 40.0f), 0.0f),
                             ImGuiCond_Appearing);
    if (ImGui::BeginPopupModal("Error##modal", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(dialogs_.errorTitle.c_str());
        ImGui::Separator();
        ImGui::PushTextWrapPos(ImGui::GetIO().DisplaySize.x - 80.0f);
        ImGui::TextUnformatted(dialogs_.errorText.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("Copy")) ImGui::SetClipboardText(dialogs_.errorText.c_str());
        ImGui::SameLine();
        if (ImGui::Button("OK", ImVec2(100, 0)) || ImGui::IsKeyPressed(GLFW_KEY_ENTER))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (dialogs_.openUnsavedModal) {
        ImGui::OpenPopup("Unsaved changes");
        dialogs_.openUnsavedModal = false;
        dialogs_.unsavedPromptOpen = true;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const std::string name =
            doc_.path().empty() ? std::string("Untitled") : fs::path(doc_.path()).filename().string();
        ImGui::Text("Save the changes to %s first?", name.c_str());
        ImGui::TextDisabled("Discarded changes cannot be undone.");
        if (ImGui::Button("Save", ImVec2(100, 0))) resolveUnsaved(UnsavedChoice::Save);
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(100, 0))) resolveUnsaved(UnsavedChoice::Discard);
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0)) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))
            resolveUnsaved(UnsavedChoice::Cancel);
        if (!dialogs_.unsavedPromptOpen) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (dialogs_.openRecoveryModal) {
        ImGui::OpenPopup("Recover unsaved work?");
        dialogs_.openRecoveryModal = false;
    }
    if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (dialogs_.recovery) {
            ImGui::Text("Aerial did not exit cleanly last time (process %d).", dialogs_.recovery->pid);
            ImGui::Text("Unsaved work on %s was autosaved.", dialogs_.recovery->documentPath.empty()
                                                                 ? "an untitled preset"
                                                                 : dialogs_.recovery->documentPath.c_str());
        }
        if (ImGui::Button("Recover", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            recover(true);
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            recover(false);
        }
        ImGui::EndPopup();
    }
}

void Editor::resolveUnsaved(UnsavedChoice choice) {
    dialogs_.unsavedPromptOpen = false;
    switch (choice) {
        case UnsavedChoice::Save:
            if (doc_.path().empty()) {
                dialogs_.continueAfterSave = true;  // the pending action runs once Save As succeeds
                saveOrSaveAs(true);
            } else if (savePresetTo(doc_.path())) {
                runPending();
            } else {
                dialogs_.pending = Pending::None;
            }
            break;
        case UnsavedChoice::Discard:
            runPending();
            break;
        case UnsavedChoice::Cancel:
            dialogs_.pending = Pending::None;
            break;
    }
}

void Editor::recover(bool accept) {
    if (!dialogs_.recovery) return;
    if (accept) {
        // The recovery file holds absolute mesh paths: back to the document's folder.
        Preset recovered = dialogs_.recovery->preset;
        const std::string& document = dialogs_.recovery->documentPath;
        rebaseMeshPaths(recovered, "", document.empty() ? std::string() : fs::path(document).parent_path().string());
        doc_.reset(recovered, document);
        doc_.markDirty();
        select({Selection::Kind::Fog, -1});
        edit_.selectedParam.reset();
        setStatus("Recovered unsaved work from " + dialogs_.recovery->recoveryFile);
        std::fprintf(stderr, "aerial-editor: recovered unsaved work from %s\n",
                     dialogs_.recovery->recoveryFile.c_str());
    } else {
        setStatus("Discarded the unsaved work of the crashed session");
    }
    Autosave::discard(*dialogs_.recovery);
    dialogs_.recovery.reset();
}

std::string Editor::exportedStatus() const {
    const std::string& summary = export_.summary();
    if (summary.find(" into " + export_.directory()) != std::string::npos)
        return "Exported for game: " + summary;
    return "Exported for game into " + export_.directory() + ": " + summary;
}

void Editor::startExport(const std::string& directory) {
    std::string error;
    // preset.json in the export names the same mesh files (relative to it).
    Preset exported = doc_.preset();
    rebaseMeshPaths(exported, doc_.path().empty() ? std::string() : fs::path(doc_.path()).parent_path().string(),
                    directory);
    if (!export_.start(exported, directory, dialogs_.exportOptions, error)) {
        showError("Cannot export for game:", error);
        return;
    }
    setStatus("Exporting for game (aerial bake) into " + directory);
}

}  // namespace aerial::editor
