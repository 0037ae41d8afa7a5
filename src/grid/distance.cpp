#include "hullinspect/grid/distance.hpp"

namespace hullinspect::grid {

void bfs_distances(const Grid<std::uint8_t>& passable, std::span<const int> sources,
                   Grid<int>& out, BfsScratch& scratch) {
  const int w = passable.width();
  const int h = passable.height();
  if (out.width() != w || out.height() != h) out = Grid<int>(w, h);
  out.fill(kUnreachable);
  auto& queue = scratch.queue;
  queue.resize(static_cast<std::size_t>(passable.size()));
  std::size_t head = 0;
  std::size_t tail = 0;
  for (int s : sources) {
    if (passable[s] && out[s] != 0) {
      out[s] = 0;
      queue[tail++] = s;
    }
  }
  while (head < tail) {
    const int i = queue[head++];
    const int x = i % w;
    const int y = i / w;
    const int next = out[i] + 1;
    for (int d = 0; d < 4; ++d) {
      const int nx = x + kNeighbourDx[d];
      const int ny = y + kNeighbourDy[d];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const int j = ny * w + nx;
      if (!passable[j] || out[j] <= next) continue;
      out[j] = next;
      queue[tail++] = j;
    }
  }
}

int label_components(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch) {
  const int w = mask.width();
  const int h = mask.height();
  if (labels.width() != w || labels.height() != h) labels = Grid<int>(w, h);
  labels.fill(-1);
  auto& queue = scratch.queue;
  queue.resize(static_cast<std::size_t>(mask.size()));
  int count = 0;
  for (int start = 0; start < mask.size(); ++start) {
    if (!mask[start] || labels[start] >= 0) continue;
    std::size_t head = 0;
    std::size_t tail = 0;
    labels[start] = count;
    queue[tail++] = start;
    while (head < tail) {
      const int i = queue[head++];
      const int x = i % w;
      const int y = i / w;
      for (int d = 0; d < 4; ++d) {
        const int nx = x + kNeighbourDx[d];
        const int ny = y + kNeighbourDy[d];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const int j = ny * w + nx;
        if (!mask[j] || labels[j] >= 0) continue;
        labels[j] = count;
        queue[tail++] = j;
      }
    }
    ++count;
  }
  return count;
}

}  // namespace hullinspect::grid
