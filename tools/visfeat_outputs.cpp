// The outputs of the visfeat tool; see visfeat_outputs.h.

#include "visfeat_outputs.h"

#include "common/arguments.h"
#include "common/cloud_input.h"
#include "common/double_xyz_cloud.h"
#include "common/output_files.h"
#include "common/tool_main.h"
#include "picture/render_picture.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace pcl::console;

namespace visfeat_tools {

namespace {

/** \brief Write a PCLPointCloud2 as binary compressed PCD to the temporary name of
 * `path`; commitOutput() moves it into place. */
bool
writeTemporary(const std::string& path,
               const pcl::PCLPointCloud2& cloud,
               const Eigen::Vector4f& origin,
               const Eigen::Quaternionf& orientation,
               std::string& error)
{
  pcl::PCDWriter writer;
  const int rc = quietly([&] {
    return writer.writeBinaryCompressed(temporaryPath(path), cloud, origin,
                                        orientation);
  });
  if (rc < 0) {
    discardOutput(path);
    error = "cannot write '" + path + "' (disk full or not writable?)";
    return false;
  }
  return true;
}

/** \brief The -voxels cloud: one PointVoxel per band cell, at the cell centre. */
pcl::PointCloud<visfeat::PointVoxel>
voxelCloud(const visfeat::VoxelBand& band,
           const visfeat::VisibilityMap& map,
           const visfeat::FeatureSegmentation& segmentation)
{
  pcl::PointCloud<visfeat::PointVoxel> cells;
  cells.resize(band.size());
  const bool have_radii = map.radii().size() == band.size();
  for (std::size_t id = 0; id < band.size(); ++id) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(id));
    const Eigen::Vector3d centre = band.grid().cellCenter(c);
    visfeat::PointVoxel& v = cells[id];
    v.x = static_cast<float>(centre.x());
    v.y = static_cast<float>(centre.y());
    v.z = static_cast<float>(centre.z());
    v.i = c.x();
    v.j = c.y();
    v.k = c.z();
    v.visibility_radius =
      have_radii ? static_cast<float>(map.radius(static_cast<visfeat::CellId>(id)))
                 : 0.f;
    const bool labeled = segmentation.cellLabels().size() == band.size();
    v.label = labeled ? segmentation.cellLabels()[id] : 0u;
    v.feature_class = static_cast<std::uint8_t>(
      labeled ? segmentation.cellClass(static_cast<visfeat::CellId>(id))
              : visfeat::FeatureClass::kNone);
  }
  cells.width = static_cast<std::uint32_t>(cells.size());
  cells.height = 1;
  cells.is_dense = true;
  return cells;
}

/** \brief `cells` (the -voxels cloud) with x y z replaced by FLOAT64 ones: the cell
 * centres plus `offset`, in the input's frame. */
pcl::PCLPointCloud2
withDoubleXYZ(const pcl::PCLPointCloud2& cells,
              const visfeat::VoxelBand& band,
              const Eigen::Vector3d& offset)
{
  std::vector<Eigen::Vector3d> centres(band.size());
  for (std::size_t id = 0; id < band.size(); ++id)
    centres[id] =
      band.grid().cellCenter(band.coord(static_cast<visfeat::CellId>(id))) + offset;
  pcl::PCLPointCloud2 xyz = visfeat_tools::doubleXYZCloud(centres);
  xyz.width = cells.width;
  xyz.height = cells.height;
  xyz.row_step = xyz.point_step * xyz.width;
  pcl::PCLPointCloud2 merged;
  pcl::concatenateFields(withoutFields(cells, {"x", "y", "z"}), xyz, merged);
  return merged;
}

/** \brief The grid and every parameter, written with a JSON graph. */
visfeat::GraphMetadata
graphMetadata(const Estimator& estimator,
              const Options& opt,
              const Eigen::Vector3d& offset)
{
  const visfeat::TopologyGraph& graph = estimator.getTopologyGraph();
  visfeat::GraphMetadata meta;
  meta.grid = estimator.getGrid();
  meta.offset = offset;
  meta.source = opt.input;
  const auto& sp = estimator.getSegmentationParameters();
  for (const std::string& w : estimator.getWarnings())
    meta.warnings.push_back(inToolTerms(w));
  for (const std::string& n : estimator.getNotes())
    meta.notes.push_back(inToolTerms(n));
  meta.parameters = {
    {"resolution", std::to_string(estimator.getResolutionEstimate().resolution)},
    {"resolution_reason", inToolTerms(estimator.getResolutionEstimate().reason)},
    {"max_search_resolution", std::to_string(estimator.getMaxSearchResolution())},
    {"copies", std::to_string(estimator.getResolutionEstimate().copies)},
    {"roughness_cells", std::to_string(estimator.getVoxelBand().roughness())},
    {"point_noise_cells", std::to_string(estimator.getPointNoise())},
    {"fill", visfeat::surfaceFillName(estimator.getSurfaceFillUsed())},
    {"fill_reason", inToolTerms(estimator.getSurfaceFillReason())},
    {"min_radius", std::to_string(sp.components.min_radius)},
    {"max_radius", std::to_string(opt.max_radius)},
    {"vertex_max_cells", std::to_string(sp.components.vertex_max_cells)},
    {"dimensionality", std::to_string(sp.components.dimensionality)},
    {"face_min_depth", std::to_string(sp.components.face_min_depth)},
    {"narrow_face_persistence", std::to_string(sp.components.narrow_face_persistence)},
    {"vertex_reach", std::to_string(sp.vertex_reach)},
    {"join_distance", std::to_string(sp.join_distance)},
    {"feature_width", std::to_string(sp.feature_width)},
    {"min_piece_cells", std::to_string(sp.min_piece_cells)},
    {"min_crease_angle", std::to_string(estimator.getMinCreaseAngle())},
    {"flat_point_variation", std::to_string(estimator.getFlatPointVariation())},
    {"raw", sp.raw ? "true" : "false"},
    {"complete_regions", sp.complete_regions ? "true" : "false"},
    {"opacity", std::to_string(opt.opacity)},
    {"noise_mode", opt.noise_mode ? "true" : "false"},
    {"paper_noise", opt.paper_noise ? "true" : "false"},
    {"smoothing_radius", std::to_string(estimator.getSmoothingRadius())},
    {"repair", opt.repair ? "true" : "false"},
    {"point_feature_distance", std::to_string(sp.point_feature_distance)},
    {"graph_dilation", std::to_string(graph.parameters().dilation_radius)},
    {"graph_min_face_contact", std::to_string(graph.parameters().min_face_contact)},
    {"graph_max_edge_faces", std::to_string(graph.parameters().max_edge_faces)},
    {"graph_vertex_faces_from_edges",
     graph.parameters().vertex_faces_from_edges ? "true" : "false"}};
  return meta;
}

} // namespace

bool
mergeFields(const pcl::PCLPointCloud2& cloud,
            const pcl::PointCloud<visfeat::PointVisibility>& result,
            pcl::PCLPointCloud2& merged,
            std::string& error)
{
  if (result.size() != static_cast<std::size_t>(cloud.width) * cloud.height) {
    error = "internal error: " + std::to_string(result.size()) + " output points for " +
            std::to_string(static_cast<std::size_t>(cloud.width) * cloud.height) +
            " input points";
    return false;
  }
  pcl::PCLPointCloud2 features;
  pcl::toPCLPointCloud2(result, features);
  features = withoutFields(features, {"x", "y", "z"});
  features.width = cloud.width;
  features.height = cloud.height;
  features.row_step = features.point_step * features.width;
  features.is_bigendian = cloud.is_bigendian;
  const pcl::PCLPointCloud2 kept =
    withoutFields(cloud, {"visibility_radius", "label", "feature_class"});
  // concatenateFields puts the second cloud's fields first: x y z ... then ours.
  if (!pcl::concatenateFields(features, kept, merged)) {
    error = "internal error: cannot concatenate the fields";
    return false;
  }
  return true;
}

bool
writeClouds(const Options& opt,
            const pcl::PCLPointCloud2& merged,
            const Eigen::Vector4f& origin,
            const Eigen::Quaternionf& orientation,
            const Estimator& estimator,
            const Eigen::Vector3d& offset,
            std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", opt.output.c_str());
  if (!writeTemporary(opt.output, merged, origin, orientation, error)) {
    print_info("\n");
    return false;
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%u", merged.width * merged.height);
  print_info(" points; fields: ");
  print_value("%s", fieldsList(merged).c_str());
  print_info("]\n");
  if (opt.voxels.empty())
    return true;
  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", opt.voxels.c_str());
  const pcl::PointCloud<visfeat::PointVoxel> cells =
    voxelCloud(estimator.getVoxelBand(), estimator.getVisibilityMap(),
               estimator.getSegmentation());
  pcl::PCLPointCloud2 cells2;
  pcl::toPCLPointCloud2(cells, cells2);
  if (!offset.isZero())
    cells2 = withDoubleXYZ(cells2, estimator.getVoxelBand(), offset);
  if (!writeTemporary(opt.voxels, cells2, Eigen::Vector4f::Zero(),
                      Eigen::Quaternionf::Identity(), error)) {
    discardOutput(opt.output);
    print_info("\n");
    return false;
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", cells.size());
  print_info(" cells]\n");
  return true;
}

bool
writeGraph(const Options& opt,
           const Estimator& estimator,
           const Eigen::Vector3d& offset,
           std::string& error)
{
  const visfeat::TopologyGraph& graph = estimator.getTopologyGraph();
  print_highlight("Saving ");
  print_value("%s ", opt.graph.c_str());
  const visfeat::GraphMetadata meta = graphMetadata(estimator, opt, offset);
  std::ofstream file(temporaryPath(opt.graph));
  const std::string ext = lowerExtension(opt.graph);
  if (ext == ".json")
    graph.writeJson(file, meta);
  else
    graph.writeDot(file, meta);
  file.close();
  if (!file) {
    discardOutput(opt.graph);
    discardOutput(opt.output);
    if (!opt.voxels.empty())
      discardOutput(opt.voxels);
    error = "cannot write '" + opt.graph + "'";
    return false;
  }
  print_info("[");
  print_value("%zu", graph.classCount(visfeat::FeatureClass::kVertex));
  print_info(" vertices, ");
  print_value("%zu", graph.classCount(visfeat::FeatureClass::kEdge));
  print_info(" edges, ");
  print_value("%zu", graph.classCount(visfeat::FeatureClass::kFace));
  print_info(" faces, ");
  print_value("%zu", graph.arcCount());
  print_info(" arcs]\n");
  return true;
}

bool
writePicturesAndCommit(const Options& opt,
                       const Estimator& estimator,
                       const pcl::PointCloud<visfeat::PointVisibility>& result,
                       std::string& error)
{
  std::vector<std::string> outputs_done{opt.output, opt.voxels, opt.graph};
  if (!opt.pictures.paths().empty()) {
    PictureOptions picture; // see picture/render_picture.h
    picture.max_radius = opt.max_radius;
    picture.cell_size = estimator.getGrid().cell_size;
    picture.band_cells = estimator.getVoxelBand().size();
    picture.title = std::filesystem::path(opt.input).filename().string();
    if (!writePictures(opt.pictures, result, estimator.getTopologyGraph(), picture,
                       error)) {
      for (const std::string& path : outputs_done)
        if (!path.empty())
          discardOutput(path);
      return false;
    }
    for (const std::string& path : opt.pictures.paths())
      outputs_done.push_back(path);
  }
  for (const std::string& path : outputs_done)
    if (!path.empty() && !commitOutput(path, error)) {
      for (const std::string& other : outputs_done)
        if (!other.empty())
          discardOutput(other);
      return false;
    }
  return true;
}

} // namespace visfeat_tools
