#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/free_space_window.h>

#include <algorithm>

namespace visfeat {

FreeSpaceWindow::FreeSpaceWindow(int bricks_per_side)
    : bricks_(bricks_per_side)
{
  if (bricks_per_side < 1 || bricks_per_side % 2 == 0 || bricks_per_side > 63)
    throw Error("free-space window: bricks a side must be odd, 1 to 63");
  side_ = bricks_ * FreeSpace::kBrickSide;
  stride_y_ = side_;
  stride_z_ = side_ * side_;
  rows_.assign(static_cast<std::size_t>(side_) * side_ * bricks_, 0);
}

void
FreeSpaceWindow::load(const FreeSpace& free_space, const Eigen::Vector3i& centre)
{
  constexpr int kSide = FreeSpace::kBrickSide;
  const Eigen::Vector3i first = centre - Eigen::Vector3i::Constant(bricks_ / 2);
  origin_ = kSide * first;
  for (int bz = 0; bz < bricks_; ++bz)
    for (int by = 0; by < bricks_; ++by)
      for (int bx = 0; bx < bricks_; ++bx) {
        const std::uint16_t* brick =
          free_space.brickRows(first + Eigen::Vector3i(bx, by, bz));
        // row (y, z) of the window: index (z side + y) bricks + bx
        std::uint16_t* out = rows_.data() + bx;
        for (int z = 0; z < kSide; ++z) {
          const std::size_t wz = static_cast<std::size_t>(bz * kSide + z);
          for (int y = 0; y < kSide; ++y) {
            const std::size_t wy = static_cast<std::size_t>(by * kSide + y);
            out[(wz * static_cast<std::size_t>(side_) + wy) *
                static_cast<std::size_t>(bricks_)] =
              brick != nullptr ? brick[y + kSide * z] : std::uint16_t{0};
          }
        }
      }
}

} // namespace visfeat
