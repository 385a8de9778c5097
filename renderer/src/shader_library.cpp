// shader_library.cpp — GLSL include resolution, compilation with logs that
// name the files, and programs that survive a failed reload.
#include "shader_library.hpp"

#include "embedded_shaders.hpp"

#include <aerial/sky.hpp>

#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string_view>

namespace aerial::renderer::detail {
namespace {

constexpr int kMaxIncludeDepth = 16;

/// Joins pieces (appending avoids GCC 12's -Wrestrict false positive on
/// chains of operator+).
std::string join(std::initializer_list<std::string_view> pieces) {
    std::string out;
    for (std::string_view p : pieces) out.append(p);
    return out;
}

bool resolveInto(const std::string& path, const ShaderReader& reader, std::string& out,
                 std::vector<std::string>& files, std::vector<std::string>& included, int depth,
                 std::string& error) {
    if (depth > kMaxIncludeDepth) {
        error = join({path, ": includes nested deeper than ", std::to_string(kMaxIncludeDepth)});
        return false;
    }
    std::string text;
    if (!reader(path, text, error)) return false;
    const int index = static_cast<int>(files.size());
    files.push_back(path);
    included.push_back(path);
    out.append("#line 1 ").append(std::to_string(index)).append("\n");
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(lines, line)) {
        ++lineNumber;
        const std::size_t start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 8, "#include") == 0) {
            const std::size_t open = line.find('"', start + 8);
            const std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
            if (close == std::string::npos) {
                error = join(
                    {path, ":", std::to_string(lineNumber), ": malformed #include (use #include \"path\")"});
                return false;
            }
            const std::string child = line.substr(open + 1, close - open - 1);
            bool seen = false;
            for (const std::string& f : included) seen = seen || f == child;
            if (!seen && !resolveInto(child, reader, out, files, included, depth + 1, error)) {
                error =
                    join({path, ":", std::to_string(lineNumber), ": in #include \"", child, "\": ", error});
                return false;
            }
            out.append(join({"#line ", std::to_string(lineNumber + 1), " ", std::to_string(index), "\n"}));
            continue;
        }
        out += line;
        out += '\n';
    }
    return true;
}

std::string fileLegend(const std::vector<std::string>& files) {
    std::string legend = "(source numbers:";
    for (std::size_t i = 0; i < files.size(); ++i) {
        legend.append(join({" ", std::to_string(i), " = ", files[i], i + 1 < files.size() ? "," : ""}));
    }
    return legend.append(")\n");
}

}  // namespace

GLuint compileStage(GLenum stage, const std::string& source, std::string& log) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string info(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
        glGetShaderInfoLog(shader, length, nullptr, info.data());
        log += info.c_str();
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

namespace {

/// Links the compiled stages into a program and deletes them; 0 with the
/// link log appended to `log` on failure.
GLuint linkStages(std::initializer_list<GLuint> stages, std::string& log) {
    const GLuint program = glCreateProgram();
    for (GLuint stage : stages) glAttachShader(program, stage);
    glLinkProgram(program);
    for (GLuint stage : stages) glDeleteShader(stage);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string info(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program, length, nullptr, info.data());
        log += info.c_str();
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

}  // namespace

GLuint linkProgram(GLuint vertexStage, GLuint fragmentStage, std::string& log) {
    return linkStages({vertexStage, fragmentStage}, log);
}

ShaderReader embeddedShaderReader() {
    return [](const std::string& path, std::string& text, std::string& error) {
        for (const EmbeddedShader& s : embeddedShaders()) {
            if (path == s.path) {
                text = s.text;
                return true;
            }
        }
        error = join({"no embedded shader \"", path, "\""});
        return false;
    };
}

ShaderReader directoryShaderReader(const std::string& directory) {
    return [directory](const std::string& path, std::string& text, std::string& error) {
        const std::string full = join({directory, "/", path});
        std::ifstream in(full, std::ios::binary);
        if (!in) {
            error = join({"cannot read shader file ", full});
            return false;
        }
        std::ostringstream buffer;
        buffer << in.rdbuf();
        text = buffer.str();
        return true;
    };
}

bool resolveIncludes(const std::string& path, const ShaderReader& reader, std::string& out,
                     std::vector<std::string>& files, std::string& error) {
    std::vector<std::string> included;
    return resolveInto(path, reader, out, files, included, 0, error);
}

GLuint buildProgram(const std::string& path, const ShaderReader& reader, std::string& log) {
    GLuint stages[2] = {0, 0};
    const GLenum kinds[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    const char* defines[2] = {"#define AERIAL_VERTEX_SHADER 1\n", "#define AERIAL_FRAGMENT_SHADER 1\n"};
    for (int k = 0; k < 2; ++k) {
        std::string body;
        std::vector<std::string> files;
        std::string error;
        if (!resolveIncludes(path, reader, body, files, error)) {
            log.append(join({path, ": ", error, "\n"}));
            for (GLuint s : stages) glDeleteShader(s);
            return 0;
        }
        std::string stageLog;
        stages[k] = compileStage(kinds[k], join({"#version 450 core\n", defines[k], body}), stageLog);
        if (stages[k] == 0) {
            log.append(join({path, k == 0 ? " (vertex stage)" : " (fragment stage)", ": compile failed ",
                             fileLegend(files), stageLog}));
            for (GLuint s : stages) glDeleteShader(s);
            return 0;
        }
    }
    std::string linkLog;
    const GLuint program = linkProgram(stages[0], stages[1], linkLog);
    if (program == 0) log.append(join({path, ": link failed: ", linkLog, "\n"}));
    return program;
}

GLuint buildComputeProgram(const std::string& path, const ShaderReader& reader, std::string& log) {
    std::string body;
    std::vector<std::string> files;
    std::string error;
    if (!resolveIncludes(path, reader, body, files, error)) {
        log.append(join({path, ": ", error, "\n"}));
        return 0;
    }
    std::string stageLog;
    const GLuint stage = compileStage(
        GL_COMPUTE_SHADER, join({"#version 450 core\n#define AERIAL_COMPUTE_SHADER 1\n", body}), stageLog);
    if (stage == 0) {
        log.append(join({path, " (compute stage): compile failed ", fileLegend(files), stageLog}));
        return 0;
    }
    std::string linkLog;
    const GLuint program = linkStages({stage}, linkLog);
    if (program == 0) log.append(join({path, ": link failed: ", linkLog, "\n"}));
    return program;
}

ShaderLibrary::~ShaderLibrary() {
    for (GLuint p : programs_) {
        if (p != 0) glDeleteProgram(p);
    }
}

const char* ShaderLibrary::fileOf(Pass pass) {
    switch (pass) {
        case Pass::Sky:
            return "sky.glsl";
        case Pass::Scene:
            return "scene.glsl";
        case Pass::GlobalFog:
            return "global_fog.glsl";
        case Pass::FogVolume:
            return "fog_volume.glsl";
        case Pass::Emitters:
            return "emitters.glsl";
        case Pass::Transparent:
            return "transparent.glsl";
        case Pass::Particles:
            return "particles.glsl";
        case Pass::FogVolumeMarched:
            return "fog_volume_marched.glsl";
        case Pass::Clouds:
            return "clouds.glsl";
        case Pass::CloudShadow:
            return "cloud_shadow.glsl";
        case Pass::CloudReconstruct:
            return "cloud_reconstruct.glsl";
        case Pass::ShadowDepth:
            return "shadow_depth.glsl";
        case Pass::FroxelInject:
            return "froxel_inject.glsl";
        case Pass::FroxelIntegrate:
            return "froxel_integrate.glsl";
        case Pass::FroxelApply:
            return "froxel_apply.glsl";
        case Pass::SubtractCrossings:
            return "subtract_crossings.glsl";
        case Pass::SubtractResolve:
            return "subtract_resolve.glsl";
        case Pass::MeshVolumeAccumulate:
            return "mesh_volume_accumulate.glsl";
        case Pass::MeshVolumeComposite:
            return "mesh_volume_composite.glsl";
        case Pass::MeshVolumeChords:
            return "mesh_volume_chords.glsl";
        case Pass::Count:
            break;
    }
    return "";
}

bool ShaderLibrary::build(const ShaderReader& reader, std::string& log) {
    bool all = true;
    for (int k = 0; k < static_cast<int>(Pass::Count); ++k) {
        const Pass pass = static_cast<Pass>(k);
        const bool compute = pass == Pass::FroxelInject || pass == Pass::FroxelIntegrate ||
                             pass == Pass::SubtractResolve || pass == Pass::MeshVolumeChords;
        const GLuint program = compute ? buildComputeProgram(fileOf(pass), reader, log)
                                       : buildProgram(fileOf(pass), reader, log);
        if (program == 0) {
            all = false;  // keep the last good program
            continue;
        }
        if (programs_[k] != 0) glDeleteProgram(programs_[k]);
        programs_[k] = program;
    }
    return all;
}

bool ShaderLibrary::complete() const {
    for (GLuint p : programs_) {
        if (p == 0) return false;
    }
    return true;
}

}  // namespace aerial::renderer::detail
