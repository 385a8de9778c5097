"""The editor's weather end to end (editor_e2e.py's case `weather`): the
viewport's weather preview darkens the picture and never touches the file;
states, overrides and regions added through the Weather panel's commands
are saved, and a region over the camera changes what the viewport draws.
Kept beside editor_e2e.py, which runs it with its own helpers."""
import os
import shutil


def mean_luma_and_chroma(image):
    """Mean Rec. 709 luma and mean chroma (max - min of R, G, B) of an 8-bit image, in 8-bit levels."""
    w, h, bpp, rows = image
    luma = chroma = 0.0
    for row in rows:
        for x in range(w):
            r, g, b = row[x * bpp], row[x * bpp + 1], row[x * bpp + 2]
            luma += 0.2126 * r + 0.7152 * g + 0.0722 * b
            chroma += max(r, g, b) - min(r, g, b)
    return luma / (w * h), chroma / (w * h)


def case_weather(env):
    """clear_summer_day at noon: previewing storm gives a darker, greyer frame
    (mean luma and chroma lower) and sets the viewport's clouds to the storm's;
    a transition played on the clock ends at the storm; none of it dirties or
    saves the document. Then a state with two overrides added by script is
    one undo step each, and the saved JSON holds it; a reserved name is
    refused with the loader's message."""
    import editor_e2e as h  # here, not at the top: editor_e2e imports this module

    source = os.path.join(env.source, "presets", "clear_summer_day.json")
    preset = env.path("summer.json")
    shutil.copyfile(source, preset)
    with open(preset, "rb") as f:
        original = f.read()
    plain, storm = env.path("plain.png"), env.path("storm.png")
    p = env.run(env.script("weather_preview.txt", """
open {preset}
time 12
show_weather on
screenshot {plain}
weather_preview storm
expect_viewport_param clouds.coverage 0.97 1e-9
expect_weather_preview storm
screenshot {storm}
print_weather
weather_preview clear:storm:0.5
expect_weather_preview clear:storm:0.5
weather_play clear storm 1.5
weather_wait
expect_weather_preview clear:storm:1
expect_viewport_param clouds.coverage 0.97 1e-9
weather_preview none
expect_viewport_param clouds.coverage 0.3 0.3
expect_clean
expect_undo 0
quit
""".format(preset=preset, plain=plain, storm=storm)))
    h.check("weather state storm: 11 overrides" in p.stdout, "print_weather did not list the storm's overrides")
    h.check("Cloud coverage: set 0.97 (keyed " in p.stdout, "print_weather did not show keyed -> storm values")
    h.check("weather clear -> storm 1.00" in p.stdout, "weather_wait did not report the transition's end")
    with open(preset, "rb") as f:
        h.check(f.read() == original, "a weather preview changed the preset file")
    plain_luma, plain_chroma = mean_luma_and_chroma(h.read_png(plain))
    storm_luma, storm_chroma = mean_luma_and_chroma(h.read_png(storm))
    print("mean luma: keyed %.1f, storm %.1f; mean chroma: keyed %.1f, storm %.1f (8-bit levels)" %
          (plain_luma, storm_luma, plain_chroma, storm_chroma))
    h.check(storm_luma < plain_luma - 5.0, "the storm preview is not darker (luma %.1f vs %.1f)" %
            (storm_luma, plain_luma))
    h.check(storm_chroma < plain_chroma, "the storm preview is not greyer (chroma %.1f vs %.1f)" %
            (storm_chroma, plain_chroma))

    # Edits: one undo step each, saved.
    window = env.path("weather_panel.png")
    env.run(env.script("weather_edit.txt", """
open {preset}
show_weather on
weather_add_state drizzle
weather_add_override drizzle clouds.coverage set 0.6
weather_add_override drizzle fog.density_per_m scale 2
expect_weather_state drizzle 2
expect_undo 3
expect_dirty
undo
expect_weather_state drizzle 1
redo
expect_weather_state drizzle 2
weather_set_override drizzle clouds.coverage add 0.25
weather_preview drizzle
expect_viewport_param clouds.coverage 0.55 0.3
window_screenshot {window}
wait_frames 2
save
expect_clean
quit
""".format(preset=preset, window=window)))
    h.read_png(window)
    saved = h.load_json(preset)
    states = {s["name"]: s for s in saved["weather"]["states"]}
    h.check(sorted(states) == ["clear", "drizzle", "overcast", "storm"], "saved states: %s" % sorted(states))
    overrides = states["drizzle"]["overrides"]
    h.check(len(overrides) == 2, "drizzle saved with %d overrides" % len(overrides))
    h.check(overrides[0] == {"param": "clouds.coverage", "add": 0.25}, "saved %s" % overrides[0])
    h.check(overrides[1] == {"param": "fog.density_per_m", "scale": 2}, "saved %s" % overrides[1])
    h.check(len(states["storm"]["overrides"]) == 11, "the storm lost overrides")

    # Regions: added around the camera's target, edited, one undo step each;
    # a region over the camera changes what the viewport draws; saved.
    regions_window = env.path("weather_regions.png")
    p = env.run(env.script("weather_regions.txt", """
open {preset}
show_weather on
expect_weather_region ridge_storm 0 0
weather_add_region valley box storm
weather_set_region valley half_extents_m 5000 5000 5000
weather_set_region valley blend_m 0
weather_set_region valley name Storm over the camera
weather_set_region valley yaw_deg 30
expect_undo 5
expect_weather_region valley 1 0
expect_viewport_param clouds.coverage 0.97 1e-9
expect_weather_preview none
weather_set_region valley state none
expect_viewport_param clouds.thickness_m 1800 1e-9
weather_set_region valley state storm
weather_remove_region ridge_storm
undo
expect_weather_region ridge_storm
print_weather
window_screenshot {window}
wait_frames 2
save
quit
""".format(preset=preset, window=regions_window)))
    h.read_png(regions_window)
    h.check("weather region valley: box at " in p.stdout and "state storm; weight 1.0000 at the camera" in p.stdout,
            "print_weather did not list the new region:\n" + p.stdout[-2000:])
    h.check("weather preview: none + regions valley 1.00" in p.stdout, "the preview does not name the region")
    regions = {r["id"]: r for r in h.load_json(preset)["weather"]["regions"]}
    h.check(sorted(regions) == ["ridge_storm", "valley"], "saved regions: %s" % sorted(regions))
    valley = regions["valley"]
    h.check(valley["shape"] == "box" and valley["state"] == "storm" and valley["blend_m"] == 0 and
            valley["half_extents_m"] == [5000, 5000, 5000] and valley["name"] == "Storm over the camera",
            "saved %s" % valley)
    h.check(abs(valley["rotation_xyzw"][1] - 0.25881904510252074) < 1e-12, "saved yaw %s" % valley)

    # A reserved name: the script fails with validatePreset's message, nothing saved.
    p = env.run(env.script("weather_none.txt", "open {preset}\nweather_add_state none\nsave\nquit\n".format(
        preset=preset)), expect_rc=1)
    h.check("\"none\" is taken" in p.stderr, "weather_add_state none: no loader message:\n" + p.stderr[-2000:])
    h.check("none" not in {s["name"] for s in h.load_json(preset)["weather"]["states"]}, "\"none\" was saved")
    print("OK: weather")
