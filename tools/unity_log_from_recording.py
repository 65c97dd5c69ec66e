#!/usr/bin/env python3
"""Writes a Unity VR playback log from a native demoplan recording (`demoplan simulate`).

The fixture generator for the Unity import: it turns a simulated recording into what a
lab's Unity logger writes, so the import is tested on another writer's conventions:

- Unity axes (left-handed, y up): Unity (x, y, z) = REP 103 (-y, z, x); quaternions
  written [w, x, y, z] with the vector part mapped the same way and negated (the change
  of axes has determinant -1);
- times in milliseconds at an irregular 15-25 Hz (steps drawn from the 90 Hz frames);
- Unity names: VR_Controller_L / VR_Controller_R, 3DPrintedCube_<colour>, Table_1 (its
  pivot on the floor, under its centre), Main Camera and XR Origin;
- grab events in the controllers' records (OnGrabPressReplay "<object>,<id>",
  OnGrabReleaseReplay) where the recording's `holding` changes;
- all velocities zero (not logged);
- the active controller missing from some steps, the idle one and the camera first
  appearing mid-log.

Deterministic: the same input and seed give the same bytes. Standard library only.

    python3 tools/unity_log_from_recording.py IN.jsonl OUT.json [--seed N]
"""

import argparse
import json
import random

COLOURS = ["red", "green", "blue", "yellow", "orange", "purple", "white", "black"]


def unity_vector(v):
    x, y, z = v
    return [-y, z, x]


def unity_quaternion(q):
    x, y, z, w = q
    # v_unity = det(M^-1) M^-1 v with M^-1 v = (-y, z, x) and det = -1.
    return [w, y, -z, -x]


def num(v):
    r = round(v, 4)
    return 0.0 if r == 0 else r


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = random.Random(args.seed)

    with open(args.input) as f:
        header = json.loads(f.readline())
        frames = [json.loads(line) for line in f if line.strip()]

    names = {}
    cubes = 0
    table = None
    for e in header["entities"]:
        if e["kind"] == "hand":
            names[e["name"]] = "VR_Controller_L" if e["name"].startswith("left") else "VR_Controller_R"
        elif e["kind"] == "cube":
            names[e["name"]] = "3DPrintedCube_" + COLOURS[cubes % len(COLOURS)]
            cubes += 1
        elif e["kind"] == "table":
            table = e
    active = "left_hand" if header.get("meta", {}).get("hand") == "left" else "right_hand"

    steps = []
    t = 0.0
    last_time = frames[-1]["t"]
    while t <= last_time + 1e-9:
        i = min(range(len(frames)), key=lambda k: abs(frames[k]["t"] - t))
        if not steps or frames[i]["t"] > steps[-1]["t"]:
            steps.append(frames[i])
        t += rng.uniform(1 / 25, 1 / 15)

    held = {}
    grab_id = 1000
    out = []
    for k, frame in enumerate(steps):
        records = []
        ents = frame["entities"]
        for native, unity in names.items():
            s = ents.get(native)
            if s is None:
                continue
            if unity.startswith("VR_Controller") and native != active and frame["t"] < 0.5:
                # The idle controller is switched on late: it first appears mid-log.
                continue
            events = []
            if unity.startswith("VR_Controller"):
                now = s.get("holding")
                before = held.get(native)
                if now != before:
                    if before is not None:
                        events.append({"name": "OnGrabReleaseReplay", "property": ""})
                    if now is not None:
                        grab_id += 1
                        events.append({"name": "OnGrabPressReplay", "property": f"{names[now]},{grab_id}"})
                    held[native] = now
                elif native == active and 5 < k < len(steps) - 5 and rng.random() < 0.06:
                    # Tracking lost for a step (never where a grab event must be written).
                    continue
            records.append(
                {
                    "name": unity,
                    "position": [num(c) for c in unity_vector(s["pos"])],
                    "orientation": [num(c) for c in unity_quaternion(s["rot"])],
                    "velocity": [0.0, 0.0, 0.0],
                    "events": events,
                }
            )
        if table is not None:
            x, y, _ = table["pose"]["pos"]
            records.append(
                {
                    "name": "Table_1",
                    "position": [num(c) for c in unity_vector([x, y, 0.0])],
                    "orientation": [1.0, 0.0, 0.0, 0.0],
                    "velocity": [0.0, 0.0, 0.0],
                    "events": [],
                }
            )
        if frame["t"] >= 1.0:
            records.append(
                {
                    "name": "Main Camera",
                    "position": [0.0, 1.6, -0.2],
                    "orientation": [1.0, 0.0, 0.0, 0.0],
                    "velocity": [0.0, 0.0, 0.0],
                    "events": [],
                }
            )
        records.append(
            {
                "name": "XR Origin",
                "position": [0.0, 0.0, 0.0],
                "orientation": [1.0, 0.0, 0.0, 0.0],
                "velocity": [0.0, 0.0, 0.0],
                "events": [],
            }
        )
        out.append((round(frame["t"] * 1000), records))

    with open(args.output, "w") as f:
        f.write('{"playbackTimestepMilliseconds": 20,\n"log": [\n')
        for n, (ms, records) in enumerate(out):
            f.write('{"time": %d, "logStep": [\n' % ms)
            f.write(",\n".join(json.dumps(r, separators=(",", ":")) for r in records))
            f.write("\n]}" + (",\n" if n + 1 < len(out) else "\n"))
        f.write("]}\n")


if __name__ == "__main__":
    main()
