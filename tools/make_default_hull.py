#!/usr/bin/python3
"""Writes data/hulls/default.txt: the built-in 230 x 30 ship side profile.

The profile is a side view of a merchant hull below the deck line, in cells of 0.5 m:
  * deck line: the top row (y = 29) along the whole length;
  * keel line: the bottom row (y = 0) from the end of the stern overhang to the start of the bow;
  * stern overhang (x < 24): the hull bottom rises towards the stern, x = 0 starts at y = 14
    (a counter stern above the propeller and rudder);
  * raked bow (x > 196): the stem slopes forward from the keel to the deck, concave (exponent 1.4).
Every column is one contiguous run of rows, so the hull is 4-connected.

Usage: /usr/bin/python3 tools/make_default_hull.py > data/hulls/default.txt
       /usr/bin/python3 tools/make_default_hull.py --size 700x70 > hull_700x70.txt

--size W×H scales the same profile to a W x H grid (deterministic; the stern, stern height and
bow start keep their proportions of the length and height), for the scale benchmarks.
"""

import argparse

A, B = 230, 30
STERN_END, STERN_HEIGHT = 24, 14
BOW_START = 196


def bottom(x: int, a: int = A, b: int = B) -> int:
    stern_end = STERN_END if a == A else round(STERN_END * a / A)
    stern_height = STERN_HEIGHT if b == B else round(STERN_HEIGHT * b / B)
    bow_start = BOW_START if a == A else round(BOW_START * a / A)
    if x < stern_end:
        return round(stern_height * (1.0 - x / stern_end) ** 1.5)
    if x > bow_start:
        return min(b - 2, round((b - 1) * ((x - bow_start) / (a - bow_start)) ** 1.4))
    return 0


def size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WxH, e.g. 700x70 (got '{text}')") from None
    if not (40 <= w <= 20000 and 8 <= h <= 4000):
        raise argparse.ArgumentTypeError(f"W must be in [40, 20000] and H in [8, 4000] (got '{text}')")
    return w, h


def main() -> None:
    parser = argparse.ArgumentParser(description="Write the default hull profile as a text mask.")
    parser.add_argument("--size", type=size, default=(A, B), help="grid W x H (default 230x30)")
    a, b = parser.parse_args().size
    if (a, b) == (A, B):
        print("; hullinspect default hull: 230 x 30 ship side profile (x = 0 stern, left; y = 0 keel, bottom)")
    else:
        print(f"; the default hull's profile scaled to {a} x {b} (x = 0 stern, left; y = 0 keel, bottom)")
    print(f"; made by tools/make_default_hull.py; 'X' hull, '.' not hull; first row is the top (y = {b - 1})")
    for y in range(b - 1, -1, -1):
        print("".join("X" if y >= bottom(x, a, b) else "." for x in range(a)))


if __name__ == "__main__":
    main()
