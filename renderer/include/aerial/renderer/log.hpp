// aerial/renderer/log.hpp — how the renderer reports problems: through a
// logger the caller passes in (sokol-style), never by crashing or printing.
#pragma once

namespace aerial::renderer {

enum class LogLevel { Debug, Info, Warning, Error };

/// A callback and its user pointer. A null function discards messages.
struct Logger {
    void (*function)(LogLevel level, const char* message, void* userData) = nullptr;
    void* userData = nullptr;
};

}  // namespace aerial::renderer
