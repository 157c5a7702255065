#!/usr/bin/env python3
"""Reads the folder written by `ccdlab cloth frames SCENE -o DIR` (standard library only).

    from cloth_frames import read_motion
    motion = read_motion("DIR")
    motion.meta["triangles"], motion.meta["springs"]   # from cloth.json
    motion.position(state, particle)                   # (x, y, z), exact doubles

As a program: prints the motion's size, or with --state S --particle P one position
(repr of the doubles: they read back exactly).
"""
import argparse
import array
import json
import os
import sys


class Motion:
    def __init__(self, meta, positions):
        self.meta = meta
        self.positions = positions  # flat array('d'): [states][particles][3]
        self.particles = meta["particles"]
        self.states = meta["steps"] + 1

    def position(self, state, particle):
        if not (0 <= state < self.states and 0 <= particle < self.particles):
            raise IndexError("state or particle out of range")
        at = (state * self.particles + particle) * 3
        return tuple(self.positions[at:at + 3])

    def state(self, state):
        """The positions of one state as a list of (x, y, z)."""
        return [self.position(state, p) for p in range(self.particles)]


def read_motion(folder):
    with open(os.path.join(folder, "cloth.json"), encoding="utf-8") as f:
        meta = json.load(f)
    if meta.get("format") != "ccdlab-cloth-motion/1":
        raise ValueError(f"{folder}/cloth.json: format: must be \"ccdlab-cloth-motion/1\"")
    positions = array.array("d")
    path = os.path.join(folder, meta["positions"]["file"])
    with open(path, "rb") as f:
        positions.frombytes(f.read())
    if sys.byteorder != "little":
        positions.byteswap()  # the file is little-endian
    expected = (meta["steps"] + 1) * meta["particles"] * 3
    if len(positions) != expected:
        raise ValueError(f"{path}: {len(positions)} doubles, expected {expected}")
    return Motion(meta, positions)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--state", type=int)
    parser.add_argument("--particle", type=int)
    args = parser.parse_args()
    try:
        motion = read_motion(args.folder)
        if args.state is not None and args.particle is not None:
            print(" ".join(repr(v) for v in motion.position(args.state, args.particle)))
        else:
            m = motion.meta
            print(f"{m['scene']}: {motion.particles} particles, {len(m['triangles'])} triangles, "
                  f"{len(m['springs']['a'])} springs, {motion.states} states of {m['step']} s")
    except (OSError, ValueError, KeyError, IndexError) as e:
        print(f"cloth_frames.py: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
