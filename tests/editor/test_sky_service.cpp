// The editor's evaluation of the document (SkyService, editor_parts.hpp)
// with an unkeyed change: dragged, it is written over the document's
// evaluation each frame without compiling (copying) the preset; at rest the
// preset with it keyed is compiled once.
#include "editor_parts.hpp"

#include <gtest/gtest.h>

namespace aerial::editor {
namespace {

ParamRef fogDensity() { return {findParam(ParamScope::Global, "fog.density_per_m"), -1}; }

TEST(SkyService, ADraggedUnkeyedChangeCompilesNoPresetPerFrame) {
    Document doc;
    doc.apply("Keys", "", [](Preset& p) {
        const double a[4] = {0.01, 0, 0, 0}, b[4] = {0.002, 0, 0, 0};
        keyParam(p, fogDensity(), 6.0);
        setValueAt(p, fogDensity(), a, 6.0);
        keyParam(p, fogDensity(), 12.0);
        setValueAt(p, fogDensity(), b, 12.0);
    });
    PendingEdits pending;
    SkyService sky;
    sky.evaluate(doc, pending, 9.0);
    const std::uint64_t before = sky.compiles;
    EXPECT_EQ(before, 1u);
    // 60 frames of a drag in the inspector, the editor evaluating twice a frame.
    for (int frame = 0; frame < 60; ++frame) {
        const double v[4] = {0.02 + 0.001 * frame, 0, 0, 0};
        ASSERT_TRUE(pending.holds(doc.preset(), fogDensity(), 9.0));
        pending.set(fogDensity(), v, 9.0);
        for (int pass = 0; pass < 2; ++pass) {
            sky.evaluate(doc, pending, 9.0, true);
            EXPECT_DOUBLE_EQ(sky.state.environment.fog.density, v[0]);
        }
    }
    EXPECT_EQ(sky.compiles, before);  // was 60: the whole preset copied and compiled each frame
    // Released: the preset with the change keyed, compiled once, shows the same.
    sky.evaluate(doc, pending, 9.0);
    sky.evaluate(doc, pending, 10.0);
    EXPECT_EQ(sky.compiles, before + 1);
    sky.evaluate(doc, pending, 9.0);
    EXPECT_DOUBLE_EQ(sky.state.environment.fog.density, 0.02 + 0.001 * 59);
    // Reverted: the document's own again, no compile.
    pending.clear();
    sky.evaluate(doc, pending, 9.0);
    EXPECT_EQ(sky.compiles, before + 1);
    double stored[4];
    readValueAt(doc.preset(), fogDensity(), 9.0, stored);
    EXPECT_DOUBLE_EQ(sky.state.environment.fog.density, stored[0]);
}

}  // namespace
}  // namespace aerial::editor
