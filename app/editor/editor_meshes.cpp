// editor_meshes.cpp — mesh fog volumes in the editor (issue 15): add one
// from a glTF file (Create > Mesh volume, the outliner's "+ Mesh", the
// script's add_mesh_volume), give a volume another mesh (the inspector's
// "Choose mesh...", set_volume_mesh), and keep the preset's relative mesh
// paths right when it is saved elsewhere (Save As) or autosaved.
//
// A mesh is read and checked (aerial/fog_mesh.hpp: closed, manifold,
// outward) before anything changes: a bad file is said in a modal naming the
// file and the reason, and the preset is left as it was. The preset stores
// the path relative to its own folder (absolute while it is untitled).
#include "editor.hpp"
#include "preset_edit.hpp"

#include <aerial/fog_mesh.hpp>

#include <filesystem>

namespace aerial::editor {

namespace fs = std::filesystem;

namespace {

std::string folderOf(const std::string& presetPath) {
    return presetPath.empty() ? std::string() : fs::path(presetPath).parent_path().string();
}

}  // namespace

void Editor::requestMeshFile(int volumeIndex) {
    dialogs_.purpose = DialogPurpose::Mesh;
    dialogs_.meshVolumeIndex = volumeIndex;
    const std::string start = doc_.path().empty() ? std::string() : folderOf(doc_.path());
    dialogs_.fileDialog.open(volumeIndex < 0 ? "Add mesh volume (glTF)" : "Choose the volume's mesh (glTF)",
                             FileDialog::Mode::Open, {".gltf", ".glb"}, start);
}

bool Editor::addMeshVolumeFromFile(const std::string& file) {
    const FogMeshLoadResult loaded = loadFogMesh(file);
    if (!loaded.mesh) {
        showError("Cannot use " + file + " as a fog volume mesh:", loaded.error);
        return false;
    }
    const glm::dvec3 ground = placeForNewObject();
    const std::string path = meshPathFor(file, doc_.path());
    int index = -1;
    doc_.apply("Add mesh volume", "", [&](Preset& p) {
        index = addMeshVolume(p, path, loaded.mesh, ground, fs::path(file).stem().string());
    });
    select({Selection::Kind::Volume, index});
    setStatus("Added " + doc_.preset().volumes[std::size_t(index)].name + " (" +
              std::to_string(loaded.mesh->triangleCount()) + " triangles from " + path + ")");
    return true;
}

bool Editor::setVolumeMesh(int volumeIndex, const std::string& file) {
    if (volumeIndex < 0 || std::size_t(volumeIndex) >= doc_.preset().volumes.size()) {
        setStatus("No volume to give a mesh: select a fog volume first");
        return false;
    }
    const FogMeshLoadResult loaded = loadFogMesh(file);
    if (!loaded.mesh) {
        showError("Cannot use " + file + " as a fog volume mesh:", loaded.error);
        return false;
    }
    const std::string path = meshPathFor(file, doc_.path());
    doc_.apply("Set mesh", "", [&](Preset& p) {
        FogVolume& v = p.volumes[std::size_t(volumeIndex)];
        v.shape = FogVolumeShape::Mesh;
        v.mesh = path;
        v.meshData = loaded.mesh;
    });
    setStatus("Mesh " + path + " (" + std::to_string(loaded.mesh->triangleCount()) + " triangles)");
    return true;
}

void Editor::rebaseMeshesForSave(const std::string& newPath) {
    const std::string from = folderOf(doc_.path()), to = folderOf(newPath);
    Preset probe = doc_.preset();
    if (rebaseMeshPaths(probe, from, to) == 0) return;
    doc_.apply("Rebase mesh paths", "", [&](Preset& p) { rebaseMeshPaths(p, from, to); });
}

}  // namespace aerial::editor
