// The editor's own action table (the Editor, built without a window): one
// entry per name, every shortcut unique in its part of the window, every
// menu item an entry that runs or draws, every script command and menu item
// of the editor before the tables were one still there with the argument
// counts it took, and every shortcut still on its action.
#include "editor.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace aerial::editor {
namespace {

const ActionTable& editorActions() {
    static const std::unique_ptr<Editor> editor = std::make_unique<Editor>(EditorOptions{});
    return editor->actions();
}

TEST(EditorActions, TheTableHasNoProblems) {
    const std::vector<std::string> problems = editorActions().problems();
    EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST(EditorActions, EveryScriptCommandNameIsUnique) {
    std::set<std::string> names;
    for (const Action& a : editorActions().all()) {
        EXPECT_TRUE(names.insert(a.name).second) << a.name << " is declared twice";
        EXPECT_EQ(editorActions().find(a.name), &a);
    }
}

TEST(EditorActions, EveryShortcutIsUniqueInItsContext) {
    std::vector<std::pair<Shortcut, std::string>> keys;
    for (const Action& a : editorActions().all())
        for (const Shortcut& s : a.keys) keys.push_back({s, a.name});
    for (std::size_t i = 0; i < keys.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            const Shortcut &s = keys[i].first, &t = keys[j].first;
            const bool overlap = s.context == KeyContext::Anywhere || t.context == KeyContext::Anywhere ||
                                 s.context == t.context;
            EXPECT_FALSE(s.key == t.key && s.modifiers == t.modifiers && overlap)
                << shortcutText(s) << " is both " << keys[j].second << "'s and " << keys[i].second << "'s";
        }
}

TEST(EditorActions, EveryShortcutHasAName) {
    // Menus and the help sheet (F1) show shortcutText; a key it does not know reads "?".
    for (const Action& a : editorActions().all())
        for (const Shortcut& s : a.keys) {
            const std::string text = shortcutText(s);
            EXPECT_FALSE(text.empty()) << a.name;
            EXPECT_EQ(text.find('?'), std::string::npos)
                << a.name << "'s key " << s.key << " shows as " << text;
        }
}

TEST(EditorActions, EveryMenuItemResolvesToAnEntry) {
    const ActionTable& table = editorActions();
    const std::vector<std::string>& menus = ActionTable::menus();
    for (const Action& a : table.all()) {
        if (a.menu.empty()) continue;
        EXPECT_NE(std::find(menus.begin(), menus.end(), a.menu), menus.end()) << a.name;
        const Action* entry = table.find(a.name);
        ASSERT_NE(entry, nullptr) << a.name;
        EXPECT_FALSE(entry->label.empty()) << a.name;
        // A menu item runs without arguments; a menu entry that is more draws itself.
        EXPECT_TRUE(entry->drawMenu || entry->runsWithoutArgs()) << a.name;
    }
    // Every item the menus had before the tables were one.
    const std::vector<std::pair<std::string, std::string>> before = {
        {"File", "New"},
        {"File", "Open..."},
        {"File", "Open Recent"},
        {"File", "Save"},
        {"File", "Save As..."},
        {"File", "Load scene (glTF)..."},
        {"File", "Built-in scene"},
        {"File", "Screenshot..."},
        {"File", "Export for game..."},
        {"File", "Export options"},
        {"File", "Quit"},
        {"Edit", "Undo"},
        {"Edit", "Redo"},
        {"Edit", "Delete"},
        {"Edit", "Duplicate"},
        {"Edit", "Key all changed parameters"},
        {"Create", "Box volume"},
        {"Create", "Ellipsoid volume"},
        {"Create", "Mesh volume (glTF)..."},
        {"Edit", "Choose mesh of the volume..."},
        {"Create", "Emitter"},
        {"Create", "Lightning"},
        {"Create", "Cloud box"},
        {"Create", "Cloud ellipsoid"},
        {"View", "OCIO display"},
        {"View", "OCIO view"},
        {"View", "Exposure offset [EV]"},
        {"View", "Resolution scale"},
        {"View", "Maximize viewport"},
        {"View", "Game view (no helpers)"},
        {"View", "Local axes"},
        {"View", "Frame selection"},
        {"View", "Timeline: whole day"},
        {"Edit", "Drop to ground"},
        {"Help", "Keys and workflow"},
        {"View", "Outliner"},
        {"View", "Inspector"},
        {"View", "Timeline"},
        {"View", "Collapse outliner"},
        {"View", "Collapse inspector"},
        {"View", "Collapse timeline"},
        {"View", "Helpers (outlines, icons, gizmo)"},
        {"View", "Ground grid"},
        {"View", "Sky"},
        {"View", "Stars"},
        {"View", "Night vision (the eye's blue night below 5 cd/m2)"},
        {"View", "Scene geometry"},
        {"View", "Global fog"},
        {"View", "Fog volumes"},
        {"View", "Emitters"},
        {"View", "Transparent objects"},
        {"View", "Fog particles"},
        {"View", "Clouds"},
        {"View", "Sun shadows"},
        {"View", "Fog as the preset says"},
        {"View", "Fog analytic (exact, no shafts)"},
        {"View", "Fog volumetric (light shafts)"},
        {"View", "Move"},
        {"View", "Rotate"},
        {"View", "Scale"},
    };
    for (const auto& [menu, label] : before) {
        const auto it = std::find_if(table.all().begin(), table.all().end(),
                                     [&](const Action& a) { return a.menu == menu && a.label == label; });
        EXPECT_NE(it, table.all().end()) << menu << " > " << label << " is gone";
    }
}

TEST(EditorActions, EveryScriptCommandOfBeforeTakesWhatItTook) {
    struct Before {
        const char* name;
        int minArgs, maxArgs;  // -1: no limit
    };
    const std::vector<Before> before = {
        {"new", 0, 0},
        {"open", 1, 1},
        {"open_expect_error", 1, 1},
        {"save", 0, 1},
        {"drop", 1, 2},
        {"load_scene", 1, 1},
        {"export", 1, 3},
        {"request_open", 1, 1},
        {"answer", 1, 1},
        {"dialog_submit", 1, 1},
        {"close_window", 0, -1},
        {"window_screenshot", 1, 1},
        {"wait_frames", 1, 1},
        {"wait_autosave", 0, -1},
        {"print", 1, 1},
        {"quit", 0, -1},
        {"expect_dirty", 0, -1},
        {"expect_clean", 0, -1},
        {"expect_status", 1, -1},
        {"expect_prompt", 0, -1},
        {"expect_no_prompt", 0, -1},
        {"expect_title", 1, 1},
        {"expect_param", 3, -1},
        {"expect_volumes", 1, 1},
        {"expect_emitters", 1, 1},
        {"expect_cloud_volumes", 1, 1},
        {"expect_undo", 1, 1},
        {"expect_keys", 2, 2},
        {"expect_selected", 1, 2},
        {"add_volume", 1, 1},
        {"add_mesh_volume", 1, 1},
        {"set_volume_mesh", 2, 2},
        {"add_emitter", 1, 1},
        {"add_cloud_volume", 1, 1},
        {"select", 1, 2},
        {"solo", 1, 2},
        {"mute", 1, 2},
        {"print_drawn", 0, 0},
        {"set_id", 3, 3},
        {"rename", 1, 1},
        {"place", 1, -1},
        {"set", 2, -1},
        {"maximize_viewport", 1, 1},
        {"collapse", 2, 2},
        {"game_view", 1, 1},
        {"print_viewport", 0, 0},
        {"autokey", 1, 1},
        {"key_pending", 0, 1},
        {"revert_pending", 0, 1},
        {"expect_pending", 1, 1},
        {"key", 1, 1},
        {"unkey", 1, 1},
        {"copy_key", 1, 1},
        {"paste_key", 1, 1},
        {"move_key", 3, 3},
        {"interp", 2, 2},
        {"wrap", 2, 2},
        {"key_all_changed", 0, -1},
        {"time", 1, 1},
        {"scrub", 3, 3},
        {"play", 2, 2},
        {"pause", 0, -1},
        {"screenshot", 1, 1},
        {"gizmo_drag", 4, 5},
        {"click", 2, 2},
        {"orbit", 2, 3},
        {"print_camera", 0, -1},
        {"gizmo_space", 1, 1},
        {"view", 1, 2},
        {"exposure", 1, 1},
        {"resolution_scale", 1, 1},
        {"curve", 2, 2},
        {"curve_select", 1, 3},
        {"inspect", 1, 1},
        {"curve_box", 2, 4},
        {"curve_move", 2, 3},
        {"curve_snap", 1, 1},
        {"curve_shift", 1, 1},
        {"curve_time", 1, 1},
        {"curve_value", 1, 1},
        {"print_curve_fields", 0, 0},
        {"print_legend", 0, 0},
        {"curve_anchor", 1, 1},
        {"curve_interp", 1, 1},
        {"print_keys", 1, 1},
        {"print_sun", 0, 0},
        {"curve_drag", 4, 5},
        {"curve_drag_box", 4, 5},
        {"curve_wheel", 2, 2},
        {"curve_pan_drag", 2, 2},
        {"curve_flat", 1, 1},
        {"curve_zoom", 2, 2},
        {"curve_pan", 1, 1},
        {"print_curves", 0, 0},
        {"request_new", 0, 0},
        {"request_quit", 0, 0},
        {"undo", 0, 0},
        {"redo", 0, 0},
        {"delete", 0, 0},
        {"duplicate", 0, 0},
        {"frame", 0, 0},
        {"timeline_fit", 0, 0},
        {"drop_to_ground", 0, 0},
        {"help_sheet", 0, 0},
    };
    for (const Before& b : before) {
        const Action* a = editorActions().find(b.name);
        ASSERT_NE(a, nullptr) << b.name << " is gone";
        EXPECT_TRUE(a->scriptable()) << b.name;
        // As many words as before still read (a switch may now also go without its on|off).
        const int most = a->extraWords ? -1 : maxArgCount(a->args);
        EXPECT_LE(minArgCount(a->args), b.minArgs) << b.name;
        EXPECT_TRUE(most == -1 || (b.maxArgs != -1 && most >= b.maxArgs)) << b.name;
    }
}

TEST(EditorActions, EveryShortcutIsStillOnItsAction) {
    const ActionTable& table = editorActions();
    const auto keysOf = [&](const char* name) {
        std::vector<std::string> keys;
        if (const Action* a = table.find(name))
            for (const Shortcut& s : a->keys) keys.push_back(shortcutText(s));
        return keys;
    };
    using Keys = std::vector<std::string>;
    const std::vector<std::pair<const char*, Keys>> want = {
        {"request_new", {"Ctrl+N"}},
        {"open_dialog", {"Ctrl+O"}},
        {"save_current", {"Ctrl+S"}},
        {"save_as", {"Ctrl+Shift+S"}},
        {"request_quit", {"Ctrl+Q"}},
        {"undo", {"Ctrl+Z"}},
        {"redo", {"Ctrl+Shift+Z", "Ctrl+Y"}},
        {"delete", {"Del"}},
        {"duplicate", {"Ctrl+D"}},
        {"add_box_volume", {"Shift+B"}},
        {"add_ellipsoid_volume", {"Shift+E"}},
        {"add_point_emitter", {"Shift+P"}},
        {"add_lightning", {"Shift+T"}},
        {"maximize_viewport", {"F11"}},
        {"game_view", {"G"}},
        {"gizmo_move", {"W"}},
        {"gizmo_rotate", {"E"}},
        {"gizmo_scale", {"R"}},
        {"gizmo_local_axes", {"L"}},
        {"frame", {"F"}},
        {"timeline_fit", {"F"}},
        {"drop_to_ground", {"End"}},
        {"preset_view", {"Home"}},
        {"help_sheet", {"F1"}},
        {"play_pause", {"Space"}},
        {"cancel_gizmo_drag", {"Esc"}},
        // The timeline's own keys, now in the table (and so in the Help sheet).
        {"timeline_delete_keys", {"Del"}},
        {"timeline_copy_key", {"Ctrl+C"}},
        {"timeline_paste_key", {"Ctrl+V"}},
    };
    for (const auto& [name, keys] : want) EXPECT_EQ(keysOf(name), keys) << name;
    EXPECT_EQ(table.find("timeline_delete_keys")->keys.front().context, KeyContext::Timeline);
    EXPECT_EQ(table.find("delete")->keys.front().context, KeyContext::OutsideTimeline);
}

TEST(EditorActions, ArgumentTypeErrorsGiveTheExactMessage) {
    const ActionTable& table = editorActions();
    std::string error;
    EXPECT_FALSE(table.runScript({"time", "26"}, error));
    EXPECT_EQ(error, "time: T \"26\" is not a time of day (HH:MM or hours in [0, 24])");
    EXPECT_FALSE(table.runScript({"wait_frames", "many"}, error));
    EXPECT_EQ(error, "wait_frames: N \"many\" is not a count (a number >= 0)");
    EXPECT_FALSE(table.runScript({"game_view", "yes"}, error));
    EXPECT_EQ(error, "game_view: on|off \"yes\" is not one of on|off");
    EXPECT_FALSE(table.runScript({"orbit", "10", "up"}, error));
    EXPECT_EQ(error, "orbit: DY \"up\" is not a number");
    EXPECT_FALSE(table.runScript({"add_volume", "sphere"}, error));
    EXPECT_EQ(error, "add_volume: SHAPE \"sphere\" is not one of box|ellipsoid");
    EXPECT_FALSE(table.runScript({"move_key", "fog.density_per_m", "6"}, error));
    EXPECT_EQ(error, "move_key: usage: move_key KEY FROM TO");
}

}  // namespace
}  // namespace aerial::editor
