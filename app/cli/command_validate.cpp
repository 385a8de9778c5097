// command_validate.cpp — `aerial validate PRESET...`: loads each preset with
// the library's loader (which runs validatePreset) and reports every issue.
//
// Text output (stdout), one line per issue, errors and warnings in file order:
//   presets/bad.json:5:40: /volumes/1/half_extents_m/1: out of range: -3 ...
//   presets/odd.json:3:34: warning: /fog/colour: unknown field ...
//   presets/good.json: ok
// then, when any preset is invalid, one summary line on stderr and exit 1.
// --json prints {"valid": bool, "presets": [{"file", "valid", "errors":
// [...], "warnings": [...]}]} with each issue as {"line", "column",
// "pointer", "message"}.
#include "cli_common.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace aerial::cli {
namespace {

struct ValidateOptions {
    std::vector<std::string> files;
    bool json = false;
};

Json issueToJson(const PresetIssue& issue) {
    return {{"file", issue.file},       {"line", issue.line},       {"column", issue.column},
            {"pointer", issue.pointer}, {"message", issue.message}, {"text", formatIssue(issue)}};
}

int runValidate(const ValidateOptions& options) {
    std::size_t invalid = 0, errorCount = 0;
    Json report = Json::array();
    for (const std::string& file : options.files) {
        const PresetLoadResult r = loadPreset(file);
        // Errors and warnings merged in file order (position, then errors first).
        std::vector<const PresetIssue*> issues;
        for (const PresetIssue& e : r.errors) issues.push_back(&e);
        for (const PresetIssue& w : r.warnings) issues.push_back(&w);
        std::stable_sort(issues.begin(), issues.end(), [](const PresetIssue* a, const PresetIssue* b) {
            if (a->line != b->line) return a->line < b->line;
            return a->column < b->column;
        });
        if (!r.ok()) ++invalid;
        errorCount += r.errors.size();
        if (options.json) {
            Json errors = Json::array(), warnings = Json::array();
            for (const PresetIssue& e : r.errors) errors.push_back(issueToJson(e));
            for (const PresetIssue& w : r.warnings) warnings.push_back(issueToJson(w));
            report.push_back({{"file", file}, {"valid", r.ok()}, {"errors", errors}, {"warnings", warnings}});
            continue;
        }
        for (const PresetIssue* issue : issues) std::cout << formatIssue(*issue) << "\n";
        if (r.ok()) {
            std::cout << file << ": ok";
            if (!r.warnings.empty())
                std::cout << " (" << r.warnings.size() << " warning" << (r.warnings.size() == 1 ? "" : "s")
                          << ")";
            std::cout << "\n";
        }
    }
    if (options.json) printJson({{"valid", invalid == 0}, {"presets", report}});
    std::cout.flush();
    if (invalid == 0) return kExitOk;
    std::cerr << "aerial validate: " << invalid << " of " << options.files.size() << " preset"
              << (options.files.size() == 1 ? "" : "s") << " invalid (" << errorCount << " error"
              << (errorCount == 1 ? "" : "s") << ")\n";
    return kExitDataError;
}

}  // namespace

Command addValidateCommand(CLI::App& parent) {
    auto options = std::make_shared<ValidateOptions>();
    CLI::App* app = parent.add_subcommand(
        "validate",
        "Check presets: every error and warning, one per line, as file:line:col: /json/pointer: reason");
    app->add_option("presets", options->files, "Preset files (JSON)")->required()->type_name("PRESET...");
    app->add_flag("--json", options->json, "Machine-readable report");
    app->footer(
        helpFooter("  aerial validate presets/*.json\n"
                   "  aerial validate my_preset.json --json"));
    return {app, [options] { return runValidate(*options); }};
}

}  // namespace aerial::cli
