// DARP on a grid that closes on itself (docs/hulls.md "Neighbours"): the two end cells of a
// linked row are 4-neighbours across the seam, so a region may hold cells on both sides of it and
// still be one connected piece.
#include "darp_workspace.hpp"

namespace hullinspect::partition::detail {

void DarpWorkspace::link_seam(const grid::EdgeSteps& flights) {
  if (flights.seam.empty()) return;
  const int last_x = padded_width_ - 3;  // the grid's last column
  seam_partner_.assign(padded_blank_.size(), -1);
  for (std::size_t y = 0; y + 1 < row_first_.size(); ++y) {
    const int first = row_first_[y];
    const int last = row_first_[y + 1] - 1;
    if (first > last || !flights.seam_links(static_cast<int>(y))) continue;
    const auto a = static_cast<std::size_t>(first);
    const auto b = static_cast<std::size_t>(last);
    if (cell_x_[a] != 0 || cell_x_[b] != last_x) continue;
    seam_ends_.push_back({first, last});
    neighbours_[4 * a + 1] = last;   // west of column 0
    neighbours_[4 * b + 0] = first;  // east of the last column
    seam_partner_[static_cast<std::size_t>(pad_of_[a])] = pad_of_[b];
    seam_partner_[static_cast<std::size_t>(pad_of_[b])] = pad_of_[a];
  }
}

void DarpWorkspace::join_across_seam() {
  for (const auto& [first, last] : seam_ends_) {
    const auto a = static_cast<std::size_t>(first);
    const auto b = static_cast<std::size_t>(last);
    if (owner_[a] != owner_[b]) continue;
    const int ra = find_root(run_of_[a]);
    const int rb = find_root(run_of_[b]);
    // The lower index becomes the root, as in the row joins.
    if (ra != rb) run_parent_[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
}

}  // namespace hullinspect::partition::detail
