#pragma once
// Sweep-Inspect's claims (docs/sweep-inspect.md, "Help"): each UAV's current target is its claim,
// and a claim holds only against UAVs no nearer to the cell than the claimer, so that a UAV that
// is done takes over a far claimer's target instead of hovering while the claimer crosses the
// hull.

namespace hullinspect::planners {

/// Whether another of `uavs` UAVs holds a claim on `cell` against UAV k: some UAV j ≠ k whose
/// claim (`claim_of(j)`, a cell or −1) is `cell` and whose flight to it (`distance(j)`) is no
/// longer than k's (`distance(k)`, asked at most once). A cell < 0 is nobody's.
template <class ClaimOf, class Distance>
bool claim_held_against(int uavs, int k, int cell, ClaimOf claim_of, Distance distance) {
  if (cell < 0) return false;
  int mine = -1;
  for (int j = 0; j < uavs; ++j) {
    if (j == k || claim_of(j) != cell) continue;
    if (mine < 0) mine = distance(k);
    if (distance(j) <= mine) return true;
  }
  return false;
}

}  // namespace hullinspect::planners
