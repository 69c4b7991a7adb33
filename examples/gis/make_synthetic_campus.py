#!/usr/bin/env python3
"""Writes synthetic_campus.geojson: a made-up park campus in real WGS84 coordinates, tagged as
OpenStreetMap tags it (natural=tree with diameter_crown, building=*, natural=wood,
highway=footway|path|pedestrian). SYNTHETIC: no place was surveyed; the coordinates put it on
open ground near 52.2053 N, 0.1218 E only so that it has real latitudes and longitudes. No
public extract was at hand offline (issue 52). Deterministic: the same file every time.

    /usr/bin/python3 examples/gis/make_synthetic_campus.py > examples/gis/synthetic_campus.geojson
"""
import json
import math
import random

LAT0, LON0 = 52.2053, 0.1218  # the south-west corner
M_PER_DEG_LAT = 111254.0      # a local approximation, only to place the data
M_PER_DEG_LON = 111412.0 * math.cos(math.radians(LAT0))


def ll(east, north):
    return [round(LON0 + east / M_PER_DEG_LON, 8), round(LAT0 + north / M_PER_DEG_LAT, 8)]


def feature(props, kind, coords):
    return {"type": "Feature", "properties": props, "geometry": {"type": kind, "coordinates": coords}}


def polygon(points, east=0.0, north=0.0):
    ring = [ll(east + x, north + y) for x, y in points]
    return [ring + [ring[0]]]


features = []
rng = random.Random(52)
# Footpaths: a loop round the lawn, a diagonal across it, a path through the wood, a pedestrian
# street along the north side; and a road, which is not a footpath.
loop = [(20, 20), (140, 20), (220, 40), (240, 120), (200, 170), (80, 180), (20, 140), (20, 20)]
features.append(feature({"highway": "footway", "name": "Lawn loop"}, "LineString", [ll(*p) for p in loop]))
features.append(feature({"highway": "footway", "name": "Diagonal"}, "LineString",
                        [ll(20, 20), ll(120, 100), ll(200, 170)]))
features.append(feature({"highway": "path", "name": "Wood path"}, "LineString",
                        [ll(240, 120), ll(280, 110), ll(320, 130), ll(350, 120)]))
features.append(feature({"highway": "pedestrian", "name": "College Walk"}, "LineString",
                        [ll(20, 140), ll(20, 220), ll(200, 220), ll(200, 170)]))
features.append(feature({"highway": "residential", "name": "Service road"}, "LineString",
                        [ll(-20, -10), ll(380, -10)]))
# Trees along the footpaths, a few metres off them, with crown diameters (some unknown).
for (ax, ay), (bx, by) in zip(loop, loop[1:]):
    length = math.hypot(bx - ax, by - ay)
    for k in range(int(length // 30)):
        s = (k + 0.5) * 30 / length
        nx, ny = -(by - ay) / length, (bx - ax) / length
        side = 4.0 if k % 2 else -4.0
        x, y = ax + s * (bx - ax) + side * nx, ay + s * (by - ay) + side * ny
        props = {"natural": "tree"}
        if rng.random() < 0.85:
            props["diameter_crown"] = str(round(rng.uniform(5, 12), 1))
        features.append(feature(props, "Point", ll(x, y)))
features.append(feature({"amenity": "bench"}, "Point", ll(60, 24)))
# Buildings: an L, a U (12 vertices) and a comb of 20 vertices, all concave.
features.append(feature({"building": "university", "name": "L Building"}, "Polygon",
                        polygon([(0, 0), (40, 0), (40, 14), (14, 14), (14, 36), (0, 36)], 40, 100)))
features.append(feature({"building": "yes", "name": "U Court"}, "Polygon",
                        polygon([(0, 0), (36, 0), (36, 30), (26, 30), (26, 10), (18, 10), (18, 24),
                                 (10, 24), (10, 10), (8, 10), (8, 30), (0, 30)], 150, 40)))
# The comb: a 50 × 15 m block with four 6 m teeth 10 m long to the north, 4 m slots between.
comb = [(0, 0), (50, 0), (50, 25), (44, 25), (44, 15), (40, 15), (40, 25), (34, 25), (34, 15),
        (30, 15), (30, 25), (24, 25), (24, 15), (20, 15), (20, 25), (14, 25), (14, 15), (10, 15),
        (10, 25), (0, 25)]
features.append(feature({"building": "dormitory", "name": "Comb Hall"}, "Polygon", polygon(comb, 250, 170)))
# A wood east of the lawn.
features.append(feature({"natural": "wood"}, "Polygon",
                        polygon([(260, 60), (360, 60), (370, 100), (360, 150), (270, 150), (250, 100)])))

print(json.dumps({"type": "FeatureCollection",
                  "name": "synthetic_campus",
                  "comment": "SYNTHETIC data made for canopy's example (examples/gis/make_synthetic_campus.py): "
                             "no real place was surveyed. CC0.",
                  "features": features}, indent=1))
