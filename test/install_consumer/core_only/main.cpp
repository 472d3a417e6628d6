// Compiled against an *installed* visfeat::core, without PCL, by
// test/install_consumer/run.cmake.
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>

#include <iostream>

int
main()
{
  const visfeat::GridSpec grid = visfeat::GridSpec::fromBounds(
    Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 2.0, 4.0), 64);
  bool refused = false;
  try {
    visfeat::GridSpec::fromBounds(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 64);
  } catch (const visfeat::Error&) {
    refused = true;
  }
  std::cout << "visfeat core consumer: dims " << grid.dims.transpose() << std::endl;
  return grid.dims.maxCoeff() >= 64 && refused ? 0 : 1;
}
