#include "hullinspect/grid/distance.hpp"

namespace hullinspect::grid {

namespace {

// The plain searches' neighbours: the grid's own 4-neighbours, none across any seam.
struct InPlane {
  int width, height;
  int operator()(int i, int d) const {
    const int nx = i % width + kNeighbourDx[d];
    const int ny = i / width + kNeighbourDy[d];
    if (nx < 0 || ny < 0 || nx >= width || ny >= height) return -1;
    return ny * width + nx;
  }
};

// grid::neighbour()'s neighbours: across the seam of `links` too.
struct AcrossSeam {
  int width, height;
  const EdgeSteps& links;
  int operator()(int i, int d) const {
    const Cell n = neighbour(Cell{i % width, i / width}, d, width, height, links);
    return n.x < 0 ? -1 : n.y * width + n.x;
  }
};

template <typename Neighbours>
void bfs(const Grid<std::uint8_t>& passable, std::span<const int> sources, Grid<int>& out,
         BfsScratch& scratch, Neighbours neighbours) {
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
    const int next = out[i] + 1;
    for (int d = 0; d < 4; ++d) {
      const int j = neighbours(i, d);
      if (j < 0 || !passable[j] || out[j] <= next) continue;
      out[j] = next;
      queue[tail++] = j;
    }
  }
}

template <typename Neighbours>
int label(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch,
          Neighbours neighbours) {
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
      for (int d = 0; d < 4; ++d) {
        const int j = neighbours(i, d);
        if (j < 0 || !mask[j] || labels[j] >= 0) continue;
        labels[j] = count;
        queue[tail++] = j;
      }
    }
    ++count;
  }
  return count;
}

}  // namespace

void bfs_distances(const Grid<std::uint8_t>& passable, std::span<const int> sources, Grid<int>& out,
                   BfsScratch& scratch) {
  bfs(passable, sources, out, scratch, InPlane{passable.width(), passable.height()});
}

void bfs_distances(const Grid<std::uint8_t>& passable, std::span<const int> sources, Grid<int>& out,
                   BfsScratch& scratch, const EdgeSteps& links) {
  if (links.seam.empty()) return bfs_distances(passable, sources, out, scratch);
  bfs(passable, sources, out, scratch, AcrossSeam{passable.width(), passable.height(), links});
}

int label_components(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch) {
  return label(mask, labels, scratch, InPlane{mask.width(), mask.height()});
}

int label_components(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch,
                     const EdgeSteps& links) {
  if (links.seam.empty()) return label_components(mask, labels, scratch);
  return label(mask, labels, scratch, AcrossSeam{mask.width(), mask.height(), links});
}

}  // namespace hullinspect::grid
