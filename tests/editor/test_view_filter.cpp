// Solo and mute (view_filter.hpp): what the viewport leaves out.
#include "view_filter.hpp"

#include <gtest/gtest.h>

namespace aerial::editor {
namespace {

PresetState twoOfEach() {
    PresetState s;
    for (const char* id : {"a", "b"}) {
        FogVolume v;
        v.id = id;
        s.volumes.push_back(v);
        Emitter e;
        e.id = id;
        s.emitters.push_back(e);
    }
    return s;
}

TEST(ViewFilter, MuteHidesOneSoloShowsOne) {
    ViewFilter f;
    EXPECT_FALSE(f.active());
    f.toggleMute(ParamScope::Volume, "a");
    PresetState shown = f.applied(twoOfEach());
    ASSERT_EQ(shown.volumes.size(), 1u);
    EXPECT_EQ(shown.volumes[0].id, "b");
    EXPECT_EQ(shown.emitters.size(), 2u);    // the emitter "a" is another object
    f.toggleSolo(ParamScope::Emitter, "b");  // solo wins over everything else
    shown = f.applied(twoOfEach());
    EXPECT_TRUE(shown.volumes.empty());
    ASSERT_EQ(shown.emitters.size(), 1u);
    EXPECT_EQ(shown.emitters[0].id, "b");
    const unsigned long long before = f.revision();
    f.toggleSolo(ParamScope::Emitter, "b");  // again: solo ends, the mute stays
    EXPECT_GT(f.revision(), before);
    EXPECT_EQ(f.applied(twoOfEach()).volumes.size(), 1u);
    f.toggleMute(ParamScope::Volume, "a");
    EXPECT_FALSE(f.active());
    EXPECT_EQ(f.applied(twoOfEach()).volumes.size(), 2u);
}

}  // namespace
}  // namespace aerial::editor
