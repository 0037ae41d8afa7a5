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
"""

A, B = 230, 30
STERN_END, STERN_HEIGHT = 24, 14
BOW_START = 196


def bottom(x: int) -> int:
    if x < STERN_END:
        return round(STERN_HEIGHT * (1.0 - x / STERN_END) ** 1.5)
    if x > BOW_START:
        return min(B - 2, round((B - 1) * ((x - BOW_START) / (A - BOW_START)) ** 1.4))
    return 0


def main() -> None:
    print("; hullinspect default hull: 230 x 30 ship side profile (x = 0 stern, left; y = 0 keel, bottom)")
    print("; made by tools/make_default_hull.py; 'X' hull, '.' not hull; first row is the top (y = 29)")
    for y in range(B - 1, -1, -1):
        print("".join("X" if y >= bottom(x) else "." for x in range(A)))


if __name__ == "__main__":
    main()
