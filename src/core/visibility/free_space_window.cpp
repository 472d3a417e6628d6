#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/free_space_window.h>

#include <cstring>

namespace visfeat {

FreeSpaceWindow::FreeSpaceWindow(int bricks_per_side)
    : bricks_(bricks_per_side)
{
  if (bricks_per_side < 1 || bricks_per_side % 2 == 0 || bricks_per_side > 63)
    throw Error("free-space window: bricks a side must be odd, 1 to 63");
  side_ = bricks_ * FreeSpace::kBrickCells;
  cells_.assign(static_cast<std::size_t>(side_) * side_ * side_, 0);
}

void
FreeSpaceWindow::load(const FreeSpace& free_space, const Eigen::Vector3i& centre)
{
  constexpr int kSide = FreeSpace::kBrickCells;
  const Eigen::Vector3i first = centre - Eigen::Vector3i::Constant(bricks_ / 2);
  origin_ = kSide * first;
  const auto side = static_cast<std::size_t>(side_);
  for (int bz = 0; bz < bricks_; ++bz)
    for (int by = 0; by < bricks_; ++by)
      for (int bx = 0; bx < bricks_; ++bx) {
        const std::uint8_t* brick =
          free_space.brickCells(first + Eigen::Vector3i(bx, by, bz));
        for (int z = 0; z < kSide; ++z)
          for (int y = 0; y < kSide; ++y) {
            std::uint8_t* out =
              cells_.data() + static_cast<std::size_t>(bx * kSide) +
              side * (static_cast<std::size_t>(by * kSide + y) +
                      side * static_cast<std::size_t>(bz * kSide + z));
            if (brick != nullptr)
              std::memcpy(out, brick + kSide * (y + kSide * z), kSide);
            else
              std::memset(out, 0, kSide);
          }
      }
}

} // namespace visfeat
