#!/usr/bin/env python3
"""The dated sun and moon of `aerial eval --json` against PyEphem (Debian
python3-ephem, libastro: VSOP87 sun, ELP-based moon), an ephemeris
independent of Aerial's NOAA / Meeus series (aerial/sun.hpp).

Over a grid and a seeded random sample of dates (1900..2100), latitudes
(-70..70), longitudes, UTC offsets and clock times:
  * sun: the geometric topocentric direction (PyEphem with pressure 0, so no
    refraction) within 0.02 deg: elevation, azimuth (times cos elevation)
    and the angle between the two directions;
  * sun apparent elevation (Aerial: Saemundsson; PyEphem: its own standard
    refraction at 1010 hPa, 10 C) within 0.02 deg where the sun stands above
    5 deg (the two refraction formulas part near the horizon);
  * moon: topocentric direction within 0.5 deg, illuminated fraction within
    0.02, bright limb angle (from the zenith through east) within 0.5 deg of
    Meeus 48.5 evaluated on PyEphem's places;
  * solar time: a dated preset in solar mode has its sun on the meridian at
    12:00 (checked at the instant `julian_day_ut` reports);
  * sun events (`sun_events`: sunrise, sunset, civil and nautical dawn and
    dusk, noon) within 0.5 min of PyEphem's risings, settings and transits.
Prints the worst error of each kind. Run:
  python3 tests/cli/ephemeris_test.py --aerial build/release/app/cli/aerial --work-dir /tmp/eph
"""
import argparse
import datetime
import json
import math
import os
import random
import subprocess
import sys

try:
    import ephem
except ImportError:
    sys.exit("ephemeris_test: PyEphem is missing (Debian python3-ephem; scripts/deps.sh installs it)")

SUN_DEG = 0.02
SUN_APPARENT_DEG = 0.02
MOON_DEG = 0.5
MOON_FRACTION = 0.02
LIMB_DEG = 0.5
# NOAA's ~0.01 deg is ~0.05 min of a sun moving 0.2 deg per minute.
EVENT_MIN = 0.5


def unit(az, el):
    return (math.cos(el) * math.sin(az), math.sin(el), math.cos(el) * math.cos(az))


def separation_deg(az1, el1, az2, el2):
    a, b = unit(az1, el1), unit(az2, el2)
    return math.degrees(math.acos(max(-1.0, min(1.0, sum(x * y for x, y in zip(a, b))))))


def wrap180(x):
    return (x + 180.0) % 360.0 - 180.0


def observer(lat, lon, when, pressure):
    o = ephem.Observer()
    o.lat, o.lon = str(lat), str(lon)
    o.elevation = 0.0
    o.pressure = pressure
    o.temp = 10.0
    o.date = when
    return o


def limb_angle_deg(lat, sidereal, sun, moon):
    """Meeus 48.5 (chi) minus the parallactic angle (14.1), from PyEphem's
    apparent places (the moon's topocentric, as Aerial uses): the bright limb
    from the zenith through east."""
    a0, d0 = float(sun.g_ra), float(sun.g_dec)
    a, d = float(moon.ra), float(moon.dec)
    chi = math.atan2(math.cos(d0) * math.sin(a0 - a),
                     math.sin(d0) * math.cos(d) - math.cos(d0) * math.sin(d) * math.cos(a0 - a))
    h = sidereal - float(moon.ra)
    dt = float(moon.dec)
    q = math.atan2(math.sin(h), math.tan(math.radians(lat)) * math.cos(dt) - math.sin(dt) * math.cos(h))
    return math.degrees(chi - q) % 360.0


class Worst:
    def __init__(self):
        self.worst = {}

    def note(self, kind, error, case):
        if error > self.worst.get(kind, (-1.0, None))[0]:
            self.worst[kind] = (error, case)


def samples():
    """(date, latitude, longitude, utc offset, hh, mm): a grid plus a seeded
    random sample."""
    out = []
    years = [1900, 1937, 1969, 2000, 2026, 2058, 2100]
    for i, year in enumerate(years):
        for month in (1, 3, 6, 9, 12):
            for lat in (-70, -45, -20, 0, 20, 45, 70):
                lon = -170.0 + ((i * 7 + month * 13 + lat) * 37) % 340
                offset = round(lon / 15.0)
                hh = (6 + 5 * month + lat // 10 + i) % 24
                out.append((f"{year:04d}-{month:02d}-{(7 * i + month) % 28 + 1:02d}", lat, lon, offset, hh, 17))
    rng = random.Random(16)
    for _ in range(300):
        y, m, d = rng.randint(1900, 2100), rng.randint(1, 12), rng.randint(1, 28)
        out.append((f"{y:04d}-{m:02d}-{d:02d}", rng.uniform(-70, 70), rng.uniform(-180, 180),
                    rng.choice([-12, -9.5, -5, -3, 0, 1, 2, 5.5, 8, 9, 12, 14]), rng.randint(0, 23),
                    rng.randint(0, 59)))
    return out


def evaluate(aerial, path, location, time):
    with open(path, "w") as f:
        json.dump({"version": 1, "location": location}, f)
    # Positions only: --no-light skips the sky solve of the light report.
    p = subprocess.run([aerial, "eval", path, "--time", time, "--json", "--no-light"], capture_output=True,
                       text=True)
    if p.returncode != 0:
        raise RuntimeError(f"aerial eval {time} failed: {p.stderr.strip()}")
    return json.loads(p.stdout)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--aerial", required=True)
    parser.add_argument("--work-dir", required=True)
    args = parser.parse_args()
    os.makedirs(args.work_dir, exist_ok=True)
    path = os.path.join(args.work_dir, "dated.json")
    worst = Worst()
    failures = []

    def check(kind, error, limit, case):
        worst.note(kind, error, case)
        if not error <= limit:
            failures.append(f"{kind}: {error:.4f} > {limit} at {case}")

    cases = samples()
    for date, lat, lon, offset, hh, mm in cases:
        case = f"{date} {hh:02d}:{mm:02d} UTC{offset:+g} lat {lat:.3f} lon {lon:.3f}"
        location = {"latitude_deg": lat, "longitude_deg": lon, "utc_offset_h": offset, "date": date,
                    "time_mode": "clock"}
        out = evaluate(args.aerial, path, location, f"{hh:02d}:{mm:02d}")
        y, m, d = (int(x) for x in date.split("-"))
        ut = datetime.datetime(y, m, d) + datetime.timedelta(hours=hh + mm / 60.0 - offset)
        geometric = observer(lat, lon, ut, 0.0)
        sun, moon = ephem.Sun(geometric), ephem.Moon(geometric)
        s, mo = out["sun"], out["moon"]
        check("sun elevation [deg]", abs(s["elevation_deg"] - math.degrees(sun.alt)), SUN_DEG, case)
        check("sun azimuth * cos(elevation) [deg]",
              abs(wrap180(s["azimuth_deg"] - math.degrees(sun.az))) * math.cos(sun.alt), SUN_DEG, case)
        check("sun direction [deg]", separation_deg(math.radians(s["azimuth_deg"]), math.radians(s["elevation_deg"]),
                                                    sun.az, sun.alt), SUN_DEG, case)
        refracted = ephem.Sun(observer(lat, lon, ut, 1010.0))
        if math.degrees(refracted.alt) > 5.0:
            check("sun apparent elevation above 5 deg [deg]",
                  abs(s["apparent_elevation_deg"] - math.degrees(refracted.alt)), SUN_APPARENT_DEG, case)
        check("moon direction [deg]", separation_deg(math.radians(mo["azimuth_deg"]),
                                                     math.radians(mo["elevation_deg"]), moon.az, moon.alt),
              MOON_DEG, case)
        check("moon illuminated fraction", abs(mo["illuminated_fraction"] - moon.moon_phase), MOON_FRACTION, case)
        if 0.02 < moon.moon_phase < 0.98:  # the limb angle is undefined at new and full moon
            limb = limb_angle_deg(lat, float(geometric.sidereal_time()), sun, moon)
            check("moon bright limb angle [deg]", abs(wrap180(mo["bright_limb_angle_deg"] - limb)), LIMB_DEG, case)

    # Solar mode: noon is the sun's transit, at the instant Aerial reports.
    for date, lat, lon in (("1900-02-11", 50.0, -120.0), ("2026-11-03", 45.0, 8.5), ("2100-07-27", -35.0, 150.0),
                           ("2026-04-15", 65.0, 25.0)):
        case = f"{date} 12:00 solar lat {lat} lon {lon}"
        out = evaluate(args.aerial, path, {"latitude_deg": lat, "longitude_deg": lon, "date": date,
                                            "time_mode": "solar"}, "12:00")
        when = ephem.Date(out["julian_day_ut"] - 2415020.0)  # PyEphem counts Dublin Julian days
        o = observer(lat, lon, when, 0.0)
        sun = ephem.Sun(o)
        hour_angle = math.degrees(float(o.sidereal_time()) - float(sun.ra))
        check("solar-mode noon hour angle [deg]", abs(wrap180(hour_angle)), SUN_DEG, case)
        check("solar-mode sun direction [deg]",
              separation_deg(math.radians(out["sun"]["azimuth_deg"]), math.radians(out["sun"]["elevation_deg"]),
                             sun.az, sun.alt), SUN_DEG, case)

    # Sun events (the anchors of keys that follow the sun): sunrise and
    # sunset with the centre at -0.833 deg, civil -6, nautical -12, noon the
    # transit -- PyEphem's rising, setting and transit with use_center and no
    # refraction (pressure 0), from the local midnight, in clock time. Places
    # where every event happens within the local day.
    for date, lat, lon, offset in (("2026-06-21", 47.37, 8.54, 2), ("2026-12-21", 47.37, 8.54, 1),
                                   ("2025-03-20", -33.87, 151.21, 11), ("2024-09-01", 40.71, -74.01, -4),
                                   ("2030-01-15", 0.0, -78.5, -5), ("1950-07-04", 35.0, 139.7, 9),
                                   ("2026-10-10", -54.8, -68.3, -3), ("2100-05-05", 19.4, -99.1, -6)):
        location = {"latitude_deg": lat, "longitude_deg": lon, "utc_offset_h": offset, "date": date,
                    "time_mode": "clock"}
        events = evaluate(args.aerial, path, location, "12:00")["sun_events"]
        y, m, d = (int(x) for x in date.split("-"))
        midnight = ephem.Date(datetime.datetime(y, m, d) - datetime.timedelta(hours=offset))
        for name, horizon, rising in (("sunrise", "-0:49.98", True), ("sunset", "-0:49.98", False),
                                      ("civil_dawn", "-6", True), ("civil_dusk", "-6", False),
                                      ("nautical_dawn", "-12", True), ("nautical_dusk", "-12", False),
                                      ("noon", None, None)):
            o = observer(lat, lon, midnight, 0.0)
            if horizon is None:
                when = o.next_transit(ephem.Sun())
            else:
                o.horizon = horizon
                when = (o.next_rising if rising else o.next_setting)(ephem.Sun(), use_center=True)
            hours = (float(when) - float(midnight)) * 24.0
            case = f"{date} {name} UTC{offset:+g} lat {lat} lon {lon}: PyEphem {hours:.4f} h"
            check("sun event time [min]", abs(events[name]["time_h"] - hours) * 60.0, EVENT_MIN, case)

    print(f"ephemeris_test: {len(cases)} clock-mode cases, PyEphem {ephem.__version__}; worst errors:")
    for kind, (error, case) in worst.worst.items():
        print(f"  {kind:42s} {error:.5f}  ({case})")
    if failures:
        print(f"{len(failures)} FAILED:\n  " + "\n  ".join(failures[:40]))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
