// label_features: visfeat in a PCL pipeline. Loads a cloud, labels every point as
// vertex / edge / face, and prints the topology graph: which vertices and faces each
// edge joins.
//
//   label_features cloud.pcd [resolution [graph.json]]   (resolution: cells along
//   the longest side, 0 = automatic; graph.json: also write the graph, with the
//   warnings, notes and the resolution's reason, as the visfeat tool does)

#include <visfeat/visibility_feature_estimation.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cstdlib>
#include <iostream>
#include <string>

int
main(int argc, char** argv)
{
  if (argc < 2) {
    std::cerr << "usage: " << argv[0] << " cloud.pcd [resolution [graph.json]]\n";
    return 1;
  }
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  if (pcl::io::loadPCDFile(argv[1], *cloud) < 0)
    return 1; // PCL has printed why

  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setInputCloud(cloud);
  est.setResolution(argc > 2 ? std::atoi(argv[2]) : 256);
  pcl::PointCloud<visfeat::PointVisibility> labels; // x y z + visfeat's fields
  est.compute(labels);
  if (labels.empty()) {
    std::cerr << "visfeat: " << est.getErrorMessage() << "\n";
    return 1;
  }

  // Per point: feature_class (0 none, 1 vertex, 2 edge, 3 face) and label (region id).
  std::size_t points[4] = {0, 0, 0, 0};
  for (const visfeat::PointVisibility& p : labels)
    ++points[p.feature_class];
  std::cout << "points: " << points[1] << " vertex, " << points[2] << " edge, "
            << points[3] << " face, " << points[0] << " none\n";

  // The graph: one node per region (ids are the points' labels), arcs between touching
  // regions of different classes.
  using visfeat::FeatureClass;
  const visfeat::TopologyGraph& graph = est.getTopologyGraph();
  std::cout << "graph: " << graph.classCount(FeatureClass::kVertex) << " vertices, "
            << graph.classCount(FeatureClass::kEdge) << " edges, "
            << graph.classCount(FeatureClass::kFace) << " faces, " << graph.arcCount()
            << " arcs\n";
  for (std::uint32_t id = 1; id <= graph.size(); ++id) {
    if (graph.node(id).feature_class != FeatureClass::kEdge)
      continue;
    std::cout << "edge " << id << " (" << graph.node(id).points << " points): vertices";
    for (std::uint32_t v : graph.verticesOfEdge(id))
      std::cout << " " << v;
    std::cout << "; faces";
    for (std::uint32_t f : graph.facesOfEdge(id))
      std::cout << " " << f;
    std::cout << "\n";
  }
  for (const std::string& warning : est.getWarnings())
    std::cout << "warning: " << warning << "\n";
  if (argc > 3) {
    // JSON (or DOT, by the extension) with what a reader needs to trust it
    visfeat::GraphMetadata meta{
      est.getGrid(), {}, argv[1], est.getWarnings(), est.getNotes()};
    meta.parameters = {{"resolution", std::to_string(est.getGrid().dims.maxCoeff())},
                       {"resolution_reason", est.getResolutionEstimate().reason}};
    graph.writeFile(argv[3], meta);
  }
  return 0;
}
