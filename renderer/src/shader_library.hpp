// shader_library.hpp — private: builds the programs from the GLSL files of
// shaders/ (one file per pass; the vertex and fragment stages are the same
// file compiled with AERIAL_VERTEX_SHADER or AERIAL_FRAGMENT_SHADER defined),
// with a small #include "path" resolver (paths relative to shaders/, each
// file included once per stage, #line directives naming the file by number).
// Sources come from the embedded copy or from a directory (hot reload); a
// program whose rebuild fails keeps its last good version.
#pragma once

#include <epoxy/gl.h>

#include <functional>
#include <string>
#include <vector>

namespace aerial::renderer::detail {

/// Reads a shader file given its path relative to shaders/; false when
/// missing (with `error` saying why).
using ShaderReader = std::function<bool(const std::string& path, std::string& text, std::string& error)>;

ShaderReader embeddedShaderReader();

ShaderReader directoryShaderReader(const std::string& directory);

/// Expands #include lines; false with `error` on a missing file or an
/// include nested deeper than 16. `files` receives the source-string numbers
/// used in #line directives (index = number).
bool resolveIncludes(const std::string& path, const ShaderReader& reader, std::string& out,
                     std::vector<std::string>& files, std::string& error);

/// Compiles one shader stage. Returns 0 and appends the compile log to `log`
/// on failure.
GLuint compileStage(GLenum stage, const std::string& source, std::string& log);

/// Links a program from two compiled stages and deletes the stages. Returns 0
/// and appends the link log to `log` on failure.
GLuint linkProgram(GLuint vertexStage, GLuint fragmentStage, std::string& log);

/// Compiles and links the program of one pass file. Returns 0 and fills
/// `log` on failure.
GLuint buildProgram(const std::string& path, const ShaderReader& reader, std::string& log);
/// The same for a compute pass: one stage, AERIAL_COMPUTE_SHADER defined.
GLuint buildComputeProgram(const std::string& path, const ShaderReader& reader, std::string& log);

/// The renderer's programs by pass.
enum class Pass {
    Sky,
    Scene,
    GlobalFog,
    FogVolume,
    Emitters,
    Transparent,
    Particles,
    FogVolumeMarched,
    Clouds,
    CloudShadow,
    CloudReconstruct,
    ShadowDepth,
    FroxelInject,     ///< compute
    FroxelIntegrate,  ///< compute
    FroxelApply,
    SubtractCrossings,
    SubtractResolve,  ///< compute
    MeshVolumeAccumulate,
    MeshVolumeComposite,
    MeshVolumeChords,  ///< compute
    Count
};

class ShaderLibrary {
public:
    ShaderLibrary() = default;
    ~ShaderLibrary();
    ShaderLibrary(const ShaderLibrary&) = delete;
    ShaderLibrary& operator=(const ShaderLibrary&) = delete;

    /// Builds every pass; programs that fail keep their previous version
    /// (none the first time). Returns true when all succeeded.
    bool build(const ShaderReader& reader, std::string& log);
    GLuint program(Pass pass) const { return programs_[static_cast<int>(pass)]; }
    bool complete() const;

    static const char* fileOf(Pass pass);

private:
    GLuint programs_[static_cast<int>(Pass::Count)] = {};
};

}  // namespace aerial::renderer::detail
