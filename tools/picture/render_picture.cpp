// Offscreen pictures of a classified cloud; see render_picture.h.

#include "picture/render_picture.h"

#include "common/output_files.h"

#include <visfeat/core/common/feature_class.h>

#include <pcl/console/print.h>
#include <pcl/console/time.h>

#include <cstdio>
#include <string>

#ifdef VISFEAT_HAVE_PICTURES
#include "picture/picture_camera.h"

#include <pcl/visualization/pcl_visualizer.h>

#include <vtkCamera.h>
#include <vtkLogger.h>
#include <vtkLookupTable.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <system_error>
#include <vector>
#endif

namespace visfeat_tools {

#ifdef VISFEAT_HAVE_PICTURES

namespace {

using visfeat::FeatureClass;

struct Rgb
{
  std::uint8_t r, g, b;
};

constexpr Rgb kVertexColor{220, 20, 30};
constexpr Rgb kEdgeColor{25, 85, 235};
constexpr Rgb kNoneColor{150, 150, 150};

/** \brief Light colours for face regions (none of them blue or red, so edges and
 * vertices stand out); face region k gets kFacePalette[k % size]. */
constexpr Rgb kFacePalette[] = {
  {236, 226, 198}, {205, 230, 200}, {240, 210, 200}, {215, 215, 215},
  {245, 236, 170}, {200, 228, 224}, {232, 214, 232}, {226, 232, 190},
};

/** \brief The colour ramp of the radius picture: from the smallest radius present
 * (blue) to the cap (red), as in the paper's Figure 3, one colour per ring count. The
 * table is built only for PictureMode::kRadius. */
struct RadiusRamp
{
  int min_radius = 0;
  int max_radius = 1;
  vtkSmartPointer<vtkLookupTable> lut;
};

bool
finite(float x, float y, float z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

bool
finite(const Eigen::Vector3d& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

pcl::PointXYZ
toPoint(const Eigen::Vector3d& p)
{
  return pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                       static_cast<float>(p.z()));
}

/** \brief Bounding box lo-hi of the finite points; returns their number. */
std::size_t
finiteBounds(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
             Eigen::Vector3d& lo,
             Eigen::Vector3d& hi)
{
  lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  hi = -lo;
  std::size_t finite_points = 0;
  for (const auto& p : cloud) {
    if (!finite(p.x, p.y, p.z))
      continue;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
    ++finite_points;
  }
  return finite_points;
}

RadiusRamp
radiusRamp(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
           const PictureOptions& options)
{
  RadiusRamp ramp;
  ramp.lut = vtkSmartPointer<vtkLookupTable>::New();
  ramp.max_radius = std::max(options.max_radius, 1);
  int min_radius = ramp.max_radius;
  for (const auto& p : cloud)
    if (std::isfinite(p.visibility_radius))
      min_radius = std::min(min_radius, static_cast<int>(p.visibility_radius));
  ramp.min_radius = std::clamp(min_radius, 0, ramp.max_radius - 1);
  if (options.mode == PictureMode::kRadius) {
    ramp.lut->SetNumberOfTableValues(ramp.max_radius - ramp.min_radius + 1);
    ramp.lut->SetHueRange(0.6667, 0.0);
    ramp.lut->SetSaturationRange(1.0, 1.0);
    ramp.lut->SetValueRange(1.0, 1.0);
    ramp.lut->SetTableRange(ramp.min_radius, ramp.max_radius);
    ramp.lut->Build();
  }
  return ramp;
}

/** \brief The colour of a point and its layer (0 none, 1 face, 2 edge, 3 vertex; in
 * the radius picture every point is in layer 0). */
Rgb
pointColor(const visfeat::PointVisibility& p,
           const PictureOptions& options,
           const RadiusRamp& ramp,
           std::size_t& layer)
{
  layer = 0;
  const auto cls = static_cast<FeatureClass>(p.feature_class);
  if (options.mode == PictureMode::kRadius) {
    if (!std::isfinite(p.visibility_radius))
      return kNoneColor;
    double rgb[3];
    ramp.lut->GetColor(
      std::clamp<double>(p.visibility_radius, ramp.min_radius, ramp.max_radius), rgb);
    return Rgb{static_cast<std::uint8_t>(std::lround(255 * rgb[0])),
               static_cast<std::uint8_t>(std::lround(255 * rgb[1])),
               static_cast<std::uint8_t>(std::lround(255 * rgb[2]))};
  }
  if (cls == FeatureClass::kVertex) {
    layer = 3;
    return kVertexColor;
  }
  if (cls == FeatureClass::kEdge) {
    layer = 2;
    return kEdgeColor;
  }
  if (cls == FeatureClass::kFace) {
    layer = 1;
    constexpr std::size_t n = sizeof(kFacePalette) / sizeof(kFacePalette[0]);
    // Region ids are dense 1..N; consecutive face ids get different colours.
    return kFacePalette[(p.label * 5u) % n];
  }
  return kNoneColor;
}

/** \brief The points, one actor per class so that edges and vertices can be drawn
 * larger (`size` + 1 pixels). */
void
addPoints(pcl::visualization::PCLVisualizer& viewer,
          const pcl::PointCloud<visfeat::PointVisibility>& cloud,
          const PictureOptions& options,
          const RadiusRamp& ramp,
          float size)
{
  std::vector<pcl::PointCloud<pcl::PointXYZRGB>::Ptr> layers(4);
  for (auto& layer : layers)
    layer.reset(new pcl::PointCloud<pcl::PointXYZRGB>);
  for (const auto& p : cloud) {
    if (!finite(p.x, p.y, p.z))
      continue;
    pcl::PointXYZRGB q;
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    std::size_t layer = 0;
    const Rgb c = pointColor(p, options, ramp, layer);
    q.r = c.r;
    q.g = c.g;
    q.b = c.b;
    layers[layer]->push_back(q);
  }
  for (std::size_t l = 0; l < layers.size(); ++l) {
    if (layers[l]->empty())
      continue;
    const std::string id = "points" + std::to_string(l);
    pcl::visualization::PointCloudColorHandlerRGBField<pcl::PointXYZRGB> colors(
      layers[l]);
    viewer.addPointCloud<pcl::PointXYZRGB>(layers[l], colors, id);
    viewer.setPointCloudRenderingProperties(
      pcl::visualization::PCL_VISUALIZER_POINT_SIZE, l >= 2 ? size + 1.0 : size, id);
  }
}

/** \brief The graph, lifted towards the camera along each node's line of sight by
 * 4% of the `diagonal` (so it projects where it is, but is not hidden by the points of
 * the surface it lies on): arcs as lines, nodes as spheres. */
void
addGraph(pcl::visualization::PCLVisualizer& viewer,
         const visfeat::TopologyGraph& graph,
         const View& view,
         double diagonal)
{
  const auto& g = graph.graph();
  const double lift = 0.04 * diagonal;
  auto lifted = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d towards = view.position - p;
    return toPoint(p + lift * towards.normalized());
  };
  const double node_radius = 0.016 * diagonal;
  std::size_t arcs = 0;
  for (auto [e, end] = boost::edges(g); e != end; ++e, ++arcs) {
    const visfeat::GraphNode& a = g[boost::source(*e, g)];
    const visfeat::GraphNode& b = g[boost::target(*e, g)];
    if (!finite(a.centroid) || !finite(b.centroid))
      continue;
    const bool has_vertex = a.feature_class == FeatureClass::kVertex ||
                            b.feature_class == FeatureClass::kVertex;
    const bool has_face =
      a.feature_class == FeatureClass::kFace || b.feature_class == FeatureClass::kFace;
    const std::string id = "arc" + std::to_string(arcs);
    // vertex-edge: black, thick; edge-face: dark grey; vertex-face: light grey.
    double grey = 0.1, width = 3.0;
    if (has_face && has_vertex) {
      grey = 0.55;
      width = 1.5;
    } else if (has_face) {
      grey = 0.35;
      width = 2.0;
    }
    viewer.addLine(lifted(a.centroid), lifted(b.centroid), grey, grey, grey, id);
    viewer.setShapeRenderingProperties(pcl::visualization::PCL_VISUALIZER_LINE_WIDTH,
                                       width, id);
  }
  for (auto [v, end] = boost::vertices(g); v != end; ++v) {
    const visfeat::GraphNode& n = g[*v];
    if (!finite(n.centroid))
      continue;
    const std::string id = "node" + std::to_string(n.id);
    if (n.feature_class == FeatureClass::kVertex)
      viewer.addSphere(lifted(n.centroid), node_radius, 0.8, 0.0, 0.05, id);
    else if (n.feature_class == FeatureClass::kEdge)
      viewer.addSphere(lifted(n.centroid), 0.55 * node_radius, 0.05, 0.2, 0.7, id);
    else if (n.feature_class == FeatureClass::kFace)
      viewer.addSphere(lifted(n.centroid), 0.55 * node_radius, 0.35, 0.35, 0.35, id);
  }
}

void
addLegendLine(pcl::visualization::PCLVisualizer& viewer,
              const std::string& text,
              int y,
              Rgb color,
              const std::string& id)
{
  viewer.addText(text, 12, y, 16, color.r / 255.0, color.g / 255.0, color.b / 255.0,
                 id);
}

/** \brief The graph's counts, bottom left, in short lines (the object rarely reaches
 * the corners). */
void
addGraphLegend(pcl::visualization::PCLVisualizer& viewer,
               const visfeat::TopologyGraph& graph)
{
  const struct
  {
    std::string text;
    Rgb color;
  } legend[] = {
    {std::to_string(graph.arcCount()) + " arcs", Rgb{40, 40, 40}},
    {std::to_string(graph.classCount(FeatureClass::kFace)) + " faces",
     Rgb{120, 120, 100}},
    {std::to_string(graph.classCount(FeatureClass::kEdge)) + " edges", kEdgeColor},
    {std::to_string(graph.classCount(FeatureClass::kVertex)) + " vertices",
     kVertexColor}};
  int legend_y = 12;
  for (const auto& line : legend) {
    addLegendLine(viewer, line.text, legend_y, line.color,
                  "legend" + std::to_string(legend_y));
    legend_y += 22;
  }
}

/** \brief The scalar bar of the radius ramp on the right and one line saying what the
 * colours mean, bottom left. */
void
addRadiusLegend(pcl::visualization::PCLVisualizer& viewer,
                vtkRenderer& renderer,
                const RadiusRamp& ramp)
{
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(ramp.lut);
  bar->SetTitle("rings");
  const int span = ramp.max_radius - ramp.min_radius;
  bar->SetNumberOfLabels(span <= 8 ? span + 1 : (span % 2 == 0 ? span / 2 + 1 : 5));
  bar->SetLabelFormat("%.0f");
  bar->SetOrientationToVertical();
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.86, 0.1);
  bar->SetWidth(0.1);
  bar->SetHeight(0.8);
  bar->UnconstrainedFontSizeOn();
  for (vtkTextProperty* text :
       {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0.1, 0.1, 0.1);
    text->SetFontSize(16);
    text->BoldOff();
    text->ItalicOff();
    text->ShadowOff();
  }
  renderer.AddActor2D(bar);
  addLegendLine(viewer,
                "visibility radius: blue = smallest (" +
                  std::to_string(ramp.min_radius) + " rings), red = cap (" +
                  std::to_string(ramp.max_radius) + " rings)",
                12, Rgb{60, 60, 60}, "legend_radius");
}

void
setCamera(vtkRenderer& renderer, const View& view)
{
  vtkCamera* camera = renderer.GetActiveCamera();
  camera->SetFocalPoint(view.focal.data());
  camera->SetPosition(view.position.data());
  camera->SetViewUp(view.up.data());
  camera->SetViewAngle(view.view_angle_deg);
  camera->SetWindowCenter(view.window_center_x, 0.0);
  renderer.ResetCameraClippingRange();
}

/** \brief Render the window and write its image to `file` as PNG; a partial file is
 * removed. */
bool
renderToPng(vtkRenderWindow* window, const std::string& file, std::string& error)
{
  if (!window->SupportsOpenGL()) {
    error = "cannot render pictures: no OpenGL 3.2 context on this display "
            "(run under xvfb-run -a, whose Mesa renderer provides one)";
    return false;
  }
  window->Render();

  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(file.c_str());
  writer->SetCompressionLevel(9);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0) {
    std::error_code ec;
    std::filesystem::remove(file, ec);
    error = "cannot write the picture '" + file + "'";
    return false;
  }
  return true;
}

} // namespace

#endif // VISFEAT_HAVE_PICTURES

bool
renderPicture(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
              const visfeat::TopologyGraph& graph,
              const PictureOptions& options,
              const std::string& file,
              std::string& error)
{
#ifndef VISFEAT_HAVE_PICTURES
  (void)cloud;
  (void)graph;
  (void)options;
  (void)file;
  return checkPictureSupport(error);
#else
  if (!checkPictureSupport(error))
    return false;
  Eigen::Vector3d lo, hi;
  const std::size_t finite_points = finiteBounds(cloud, lo, hi);
  if (finite_points == 0) {
    error = "cannot render a picture: the cloud has no finite points";
    return false;
  }
  // An organized cloud is seen as its sensor saw it; any other from the direction that
  // shows the most faces. Both pictures of a run share the camera.
  Eigen::Vector3d direction, up;
  const bool organized = sensorView(cloud, direction, up);
  if (!organized)
    direction = chooseDirection(cloud);
  const View view = fitView(cloud, lo, hi, direction, options.width, options.height,
                            options.mode == PictureMode::kRadius ? 0.18 : 0.0,
                            organized ? &up : nullptr);
  const float size =
    pointSize(options.cell_size, options.band_cells, finite_points, view);
  const double diagonal = std::max((hi - lo).norm(), 1e-9);

  // VTK's deprecation warnings about PCL's shader calls are noise here; errors stay.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  std::string why;
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(xDisplay(why)); // not closed by VTK: it does not own it
  window->SetOffScreenRendering(1);
  window->SetSize(options.width, options.height);
  window->SetMultiSamples(8);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  pcl::visualization::PCLVisualizer viewer(renderer, window, "visfeat", false);
  viewer.setBackgroundColor(1.0, 1.0, 1.0);
  viewer.setSize(options.width, options.height);

  const RadiusRamp ramp = radiusRamp(cloud, options);
  addPoints(viewer, cloud, options, ramp, size);
  if (options.mode == PictureMode::kClasses) {
    addGraph(viewer, graph, view, diagonal);
    addGraphLegend(viewer, graph);
  } else {
    addRadiusLegend(viewer, *renderer, ramp);
  }
  if (!options.title.empty())
    viewer.addText(options.title, 12, options.height - 30, 18, 0.1, 0.1, 0.1, "title");
  setCamera(*renderer, view);
  return renderToPng(window, file, error);
#endif
}

bool
writePictures(const PictureRequests& requests,
              const pcl::PointCloud<visfeat::PointVisibility>& cloud,
              const visfeat::TopologyGraph& graph,
              PictureOptions options,
              std::string& error)
{
  using namespace pcl::console;
  options.width = requests.width;
  options.height = requests.height;
  pcl::console::TicToc tt;
  tt.tic();
  print_highlight("Rendering ");
  for (const std::string& path : requests.paths()) {
    print_value("%s ", path.c_str());
    std::fflush(stdout);
    options.mode =
      path == requests.classes ? PictureMode::kClasses : PictureMode::kRadius;
    if (!renderPicture(cloud, graph, options, temporaryPath(path), error)) {
      print_info("\n");
      for (const std::string& p : requests.paths())
        discardOutput(p);
      return false;
    }
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : %dx%d]\n", options.width, options.height);
  return true;
}

} // namespace visfeat_tools
