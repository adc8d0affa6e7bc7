// A 2D or 3D grid of labels: the example model E and the output model M of discrete
// model synthesis (Merrell, ch. 3). Cell (x, y, z) is stored at x + nx * (y + ny * z);
// z is "up" (a 2D model has nz = 1). A label is an index into Example::labels; -1 marks
// an unassigned cell.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis {

constexpr int32_t kUnassigned = -1;

struct GridSize {
  int nx = 1, ny = 1, nz = 1;

  int64_t count() const { return int64_t(nx) * ny * nz; }
  int operator[](int axis) const { return axis == 0 ? nx : axis == 1 ? ny : nz; }
  bool operator==(const GridSize&) const = default;
};

struct Cell {
  int x = 0, y = 0, z = 0;
  bool operator==(const Cell&) const = default;
};

class LabelGrid {
 public:
  LabelGrid() = default;
  LabelGrid(GridSize size, int32_t fill = kUnassigned)
      : size_(size), cells_(size_t(size.count()), fill) {}

  const GridSize& size() const { return size_; }
  int64_t cellCount() const { return size_.count(); }
  int64_t index(int x, int y, int z) const { return x + int64_t(size_.nx) * (y + int64_t(size_.ny) * z); }
  Cell cell(int64_t index) const {
    return {int(index % size_.nx), int((index / size_.nx) % size_.ny),
            int(index / (int64_t(size_.nx) * size_.ny))};
  }
  bool inside(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < size_.nx && y < size_.ny && z < size_.nz;
  }
  int32_t at(int x, int y, int z) const { return cells_[size_t(index(x, y, z))]; }
  int32_t& at(int x, int y, int z) { return cells_[size_t(index(x, y, z))]; }
  int32_t operator[](int64_t i) const { return cells_[size_t(i)]; }
  int32_t& operator[](int64_t i) { return cells_[size_t(i)]; }

  std::vector<int32_t>& data() { return cells_; }
  const std::vector<int32_t>& data() const { return cells_; }

  bool operator==(const LabelGrid&) const = default;

 private:
  GridSize size_;
  std::vector<int32_t> cells_;
};

}  // namespace fgsg::rt::synthesis
