// Offscreen pictures of a classified cloud; see render_picture.h.

#include "render_picture.h"

#include <visfeat/core/common/feature_class.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include <dlfcn.h>

#include <pcl/console/print.h>
#include <pcl/console/time.h>

#ifdef VISFEAT_HAVE_PICTURES
#include <pcl/visualization/pcl_visualizer.h>

#include <Eigen/Eigenvalues>

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
#endif

#include <filesystem>

namespace visfeat_tools {

namespace {

/** \brief The X connection every picture renders through, opened once and kept open
 * until the process exits (nullptr when none could be opened; `why` says why).
 *
 * Xlib is loaded at run time (VTK loads it anyway), so the tool needs no X headers.
 * VTK 9.1 calls abort() when it cannot open a display, so this is checked before VTK
 * is touched. Sharing one connection matters under xvfb-run: an X server resets when
 * its last client disconnects, and a window opened during the reset finds no server
 * (VTK aborts on the second picture). */
void*
xDisplay(std::string& why)
{
  static std::string problem;
  static void* const display = []() -> void* {
    const char* name = std::getenv("DISPLAY");
    if (name == nullptr || *name == '\0') {
      problem = "no X display (DISPLAY is not set)";
      return nullptr;
    }
    void* xlib = dlopen("libX11.so.6", RTLD_NOW | RTLD_GLOBAL);
    if (xlib == nullptr) {
      problem = "libX11.so.6 cannot be loaded";
      return nullptr;
    }
    using OpenDisplay = void* (*)(const char*);
    const auto open_display =
      reinterpret_cast<OpenDisplay>(dlsym(xlib, "XOpenDisplay"));
    if (open_display == nullptr) {
      problem = "libX11.so.6 has no XOpenDisplay";
      return nullptr;
    }
    void* connection = open_display(nullptr);
    if (connection == nullptr)
      problem = std::string("cannot open the X display '") + name + "'";
    return connection;
  }();
  why = problem;
  return display;
}

#ifdef VISFEAT_HAVE_PICTURES

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

void
fail(std::string& error, const std::string& message)
{
  error = message;
}

/** \brief The default direction the camera looks from (towards the object): the
 * bounding-box diagonal (1,1,1), tilted a little so that opposite corners of a box do
 * not project onto each other. */
const Eigen::Vector3d kDefaultDirection = Eigen::Vector3d(1.0, 0.78, 0.62).normalized();

/** \brief The direction to look from: the one that shows the most surface.
 *
 * Each planar face region (its points' smallest covariance eigenvalue below 1% of the
 * middle one) contributes its point count times |normal . d|: for a convex object that
 * is its projected area, largest from a corner-like direction showing three faces at
 * once (an isometric view for a cube, tilted towards the big faces for a flat box).
 * Among the directions within 3% of the best, the one closest to kDefaultDirection
 * wins (deterministic, and never exactly along a diagonal). Without planar faces (raw
 * mode, smooth objects): kDefaultDirection. */
Eigen::Vector3d
chooseDirection(const pcl::PointCloud<visfeat::PointVisibility>& cloud)
{
  struct Moments
  {
    double n = 0.0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  };
  std::map<std::uint32_t, Moments> faces;
  for (const auto& p : cloud) {
    if (p.feature_class != static_cast<std::uint8_t>(visfeat::FeatureClass::kFace) ||
        !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    Moments& m = faces[p.label];
    const Eigen::Vector3d q(p.x, p.y, p.z);
    m.n += 1.0;
    m.sum += q;
    m.outer += q * q.transpose();
  }
  std::vector<std::pair<Eigen::Vector3d, double>> normals; // normal, weight
  for (const auto& [label, m] : faces) {
    (void)label;
    if (m.n < 10.0)
      continue;
    const Eigen::Vector3d mean = m.sum / m.n;
    const Eigen::Matrix3d cov = m.outer / m.n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    if (eig.info() != Eigen::Success ||
        eig.eigenvalues()(0) > 0.01 * eig.eigenvalues()(1))
      continue;
    normals.emplace_back(eig.eigenvectors().col(0), m.n);
  }
  if (normals.empty())
    return kDefaultDirection;

  // Directions spread evenly over the sphere (a Fibonacci lattice).
  constexpr int kCandidates = 2000;
  std::vector<Eigen::Vector3d> candidates;
  std::vector<double> scores;
  double best = 0.0;
  for (int i = 0; i < kCandidates; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kCandidates;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
    const Eigen::Vector3d d(r * std::cos(phi), r * std::sin(phi), z);
    double score = 0.0;
    for (const auto& [n, w] : normals)
      score += w * std::abs(n.dot(d));
    candidates.push_back(d);
    scores.push_back(score);
    best = std::max(best, score);
  }
  Eigen::Vector3d chosen = kDefaultDirection;
  double closest = -2.0;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (scores[i] >= 0.97 * best && candidates[i].dot(kDefaultDirection) > closest) {
      closest = candidates[i].dot(kDefaultDirection);
      chosen = candidates[i];
    }
  return chosen.normalized();
}

/** \brief The camera: perspective, looking from `direction`; the longer axis of the
 * object on screen horizontal (the frame is wider than high) unless the object looks
 * round from there (then world z is up); centred on the object's projected box, at the
 * distance where every point is inside `fill` of the frame. */
struct View
{
  Eigen::Vector3d focal, position, up;
  double view_angle_deg = 30.0;
  double pixels_per_unit = 1.0; // at the focal point
  /** \brief vtkCamera::SetWindowCenter x: shifts the object left of the frame's
   * centre when the right side is reserved (for the scalar bar). */
  double window_center_x = 0.0;
};

View
fitView(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
        const Eigen::Vector3d& lo,
        const Eigen::Vector3d& hi,
        const Eigen::Vector3d& direction,
        int width,
        int height,
        double right_reserve)
{
  View v;
  const Eigen::Vector3d d = direction.normalized();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);

  // Spread of the points in the image plane.
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  double n = 0.0;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - centre;
    q -= q.dot(d) * d;
    cov += q * q.transpose();
    n += 1.0;
  }
  Eigen::Vector3d up;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov / std::max(n, 1.0));
  // eigenvalues ascending: 0 ~ along d, 1 minor, 2 major in-plane axis.
  if (eig.info() == Eigen::Success &&
      eig.eigenvalues()(2) > 1.3 * eig.eigenvalues()(1)) {
    up = d.cross(eig.eigenvectors().col(2)).normalized(); // major axis horizontal
  } else {
    const Eigen::Vector3d world_up =
      std::abs(d.z()) < 0.95 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    up = (world_up - world_up.dot(d) * d).normalized();
  }
  if (up.z() < 0.0)
    up = -up;
  const Eigen::Vector3d right = up.cross(d);

  // Centre the projected box, then the nearest distance that keeps every point inside
  // the frame (perspective: x / (D - z) <= tan of the half angle).
  Eigen::Vector2d min2 = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d max2 = -min2;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - centre;
    const Eigen::Vector2d xy(q.dot(right), q.dot(up));
    min2 = min2.cwiseMin(xy);
    max2 = max2.cwiseMax(xy);
  }
  const Eigen::Vector2d mid = 0.5 * (min2 + max2);
  v.focal = centre + mid.x() * right + mid.y() * up;
  constexpr double kFill = 0.86; // of the half width / height
  const double half_v = 0.5 * v.view_angle_deg * M_PI / 180.0;
  const double tan_v = std::tan(half_v) * kFill;
  // The object fills the left (1 - right_reserve) of the frame: its centre appears at
  // -right_reserve in normalised [-1, 1] coordinates (window centre +right_reserve).
  const double tan_h =
    std::tan(half_v) * width / height * kFill * (1.0 - right_reserve);
  v.window_center_x = right_reserve;
  double distance = 1e-9;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - v.focal;
    const double z = q.dot(d);
    distance = std::max(distance, z + std::abs(q.dot(right)) / tan_h);
    distance = std::max(distance, z + std::abs(q.dot(up)) / tan_v);
  }
  distance = std::max(distance, 1e-6 * (hi - lo).norm());
  v.position = v.focal + distance * d;
  v.up = up;
  v.pixels_per_unit = height / (2.0 * distance * std::tan(half_v));
  return v;
}

/** \brief Point size in pixels: about 2.2 times the estimated point spacing on screen,
 * so that the surfaces look closed. Spacing: sqrt(area / points), the area estimated
 * as band cells x cell size^2. */
float
pointSize(const PictureOptions& options, std::size_t points, const View& view)
{
  if (points == 0 || options.cell_size <= 0.0 || options.band_cells == 0)
    return 2.f;
  const double spacing =
    options.cell_size * std::sqrt(static_cast<double>(options.band_cells) / points);
  const double pixels = 2.2 * spacing * view.pixels_per_unit;
  return static_cast<float>(std::clamp(std::round(pixels), 2.0, 10.0));
}

pcl::PointXYZ
toPoint(const Eigen::Vector3d& p)
{
  return pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                       static_cast<float>(p.z()));
}

bool
finite(const Eigen::Vector3d& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
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

#endif // VISFEAT_HAVE_PICTURES

} // namespace

bool
picturesCompiledIn()
{
#ifdef VISFEAT_HAVE_PICTURES
  return true;
#else
  return false;
#endif
}

bool
checkPictureSupport(std::string& error)
{
  if (!picturesCompiledIn()) {
    error = "this visfeat was built without PCL's visualization module (VTK), so it "
            "cannot write pictures; install libpcl-dev with VTK and rebuild";
    return false;
  }
  std::string why;
  if (xDisplay(why) == nullptr) {
    error = "cannot render pictures: " + why +
            "; VTK here needs an X display even offscreen: run under xvfb-run -a "
            "(Debian package xvfb)";
    return false;
  }
  return true;
}

bool
parsePictureSize(const std::string& text, int& width, int& height, std::string& error)
{
  const std::size_t x = text.find_first_of("xX");
  auto number = [](const std::string& s, int& value) {
    if (s.empty() || s.size() > 5 ||
        !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return false;
    value = std::stoi(s);
    return value >= PictureOptions::kMinSize && value <= PictureOptions::kMaxSize;
  };
  int w = 0, h = 0;
  if (x == std::string::npos || !number(text.substr(0, x), w) ||
      !number(text.substr(x + 1), h)) {
    error = "-png_size '" + text + "' must be WIDTHxHEIGHT, each " +
            std::to_string(PictureOptions::kMinSize) + "-" +
            std::to_string(PictureOptions::kMaxSize) + " pixels (e.g. 800x600)";
    return false;
  }
  width = w;
  height = h;
  return true;
}

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
  using visfeat::FeatureClass;
  if (!checkPictureSupport(error))
    return false;

  // Bounds of the finite points.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  std::size_t finite_points = 0;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
    ++finite_points;
  }
  if (finite_points == 0) {
    fail(error, "cannot render a picture: the cloud has no finite points");
    return false;
  }
  const View view =
    fitView(cloud, lo, hi, chooseDirection(cloud), options.width, options.height,
            options.mode == PictureMode::kRadius ? 0.18 : 0.0);
  const float size = pointSize(options, finite_points, view);
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

  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  const int max_radius = std::max(options.max_radius, 1);
  // The ramp runs from the smallest radius present (blue) to the cap (red), as in the
  // paper's Figure 3, one colour per ring count.
  int min_radius = max_radius;
  for (const auto& p : cloud)
    if (std::isfinite(p.visibility_radius))
      min_radius = std::min(min_radius, static_cast<int>(p.visibility_radius));
  min_radius = std::clamp(min_radius, 0, max_radius - 1);
  if (options.mode == PictureMode::kRadius) {
    lut->SetNumberOfTableValues(max_radius - min_radius + 1);
    lut->SetHueRange(0.6667, 0.0);
    lut->SetSaturationRange(1.0, 1.0);
    lut->SetValueRange(1.0, 1.0);
    lut->SetTableRange(min_radius, max_radius);
    lut->Build();
  }
  // The points, one actor per class so that edges and vertices can be drawn larger.
  std::vector<pcl::PointCloud<pcl::PointXYZRGB>::Ptr> layers(4);
  for (auto& layer : layers)
    layer.reset(new pcl::PointCloud<pcl::PointXYZRGB>);
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    pcl::PointXYZRGB q;
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    Rgb c = kNoneColor;
    std::size_t layer = 0;
    const auto cls = static_cast<FeatureClass>(p.feature_class);
    if (options.mode == PictureMode::kRadius) {
      if (std::isfinite(p.visibility_radius)) {
        double rgb[3];
        lut->GetColor(std::clamp<double>(p.visibility_radius, min_radius, max_radius),
                      rgb);
        c = Rgb{static_cast<std::uint8_t>(std::lround(255 * rgb[0])),
                static_cast<std::uint8_t>(std::lround(255 * rgb[1])),
                static_cast<std::uint8_t>(std::lround(255 * rgb[2]))};
      }
    } else if (cls == FeatureClass::kVertex) {
      c = kVertexColor;
      layer = 3;
    } else if (cls == FeatureClass::kEdge) {
      c = kEdgeColor;
      layer = 2;
    } else if (cls == FeatureClass::kFace) {
      constexpr std::size_t n = sizeof(kFacePalette) / sizeof(kFacePalette[0]);
      // Region ids are dense 1..N; consecutive face ids get different colours.
      c = kFacePalette[(p.label * 5u) % n];
      layer = 1;
    }
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

  // The graph, lifted towards the camera along each node's line of sight (so it
  // projects where it is, but is not hidden by the points of the surface it lies on).
  int legend_y = 12;
  if (options.mode == PictureMode::kClasses) {
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
      const bool has_face = a.feature_class == FeatureClass::kFace ||
                            b.feature_class == FeatureClass::kFace;
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
    // Bottom left, short lines (the object rarely reaches the corners).
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
    for (const auto& line : legend) {
      addLegendLine(viewer, line.text, legend_y, line.color,
                    "legend" + std::to_string(legend_y));
      legend_y += 22;
    }
  } else {
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(lut);
    bar->SetTitle("rings");
    const int span = max_radius - min_radius;
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
    renderer->AddActor2D(bar);
    addLegendLine(viewer,
                  "visibility radius: blue = smallest (" + std::to_string(min_radius) +
                    " rings), red = cap (" + std::to_string(max_radius) + " rings)",
                  legend_y, Rgb{60, 60, 60}, "legend_radius");
  }
  if (!options.title.empty())
    viewer.addText(options.title, 12, options.height - 30, 18, 0.1, 0.1, 0.1, "title");

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(view.focal.data());
  camera->SetPosition(view.position.data());
  camera->SetViewUp(view.up.data());
  camera->SetViewAngle(view.view_angle_deg);
  camera->SetWindowCenter(view.window_center_x, 0.0);
  renderer->ResetCameraClippingRange();

  if (!window->SupportsOpenGL()) {
    fail(error, "cannot render pictures: no OpenGL 3.2 context on this display "
                "(run under xvfb-run -a, whose Mesa renderer provides one)");
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
    fail(error, "cannot write the picture '" + file + "'");
    return false;
  }
  return true;
#endif
}

std::vector<std::string>
PictureRequests::paths() const
{
  std::vector<std::string> out;
  for (const std::string& p : {classes, radius})
    if (!p.empty())
      out.push_back(p);
  return out;
}

void
printPictureHelp()
{
  using namespace pcl::console;
  print_info("    -png out.png      = also render a picture: vertices red, edges blue, "
             "faces pastel, with the topology graph\n");
  print_info(
    "    -png_radius out.png = also render the visibility map (blue = smallest "
    "radius, red = max_radius)\n");
  print_info("    -png_size WxH     = size of the pictures (default: ");
  print_value("1024x768");
  print_info(" pixels)\n");
  print_info("  Pictures are rendered offscreen with VTK, which needs an X display: "
             "on a headless machine run under xvfb-run -a.%s\n",
             picturesCompiledIn() ? "" : " (Not available in this build.)");
}

bool
parsePictureRequests(const Arguments& args,
                     const std::vector<std::string>& other_outputs,
                     PictureRequests& requests,
                     std::string& error)
{
  requests = PictureRequests();
  if (args.has("-png_size") &&
      !parsePictureSize(args.value("-png_size"), requests.width, requests.height,
                        error))
    return false;
  for (const char* option : {"-png", "-png_radius"}) {
    if (!args.has(option))
      continue;
    const std::string path = args.value(option);
    if (path.empty()) {
      error = std::string(option) + " needs a file name";
      return false;
    }
    if (lowerExtension(path) != ".png") {
      error = "picture '" + path + "' must have the extension .png";
      return false;
    }
    for (const std::string& other : other_outputs)
      if (path == other) {
        error =
          std::string("the ") + option + " file must differ from the other outputs";
        return false;
      }
    if (!checkWritable(path, error))
      return false;
    (std::string(option) == "-png" ? requests.classes : requests.radius) = path;
  }
  if (!requests.classes.empty() && requests.classes == requests.radius) {
    error = "the -png and -png_radius files must differ";
    return false;
  }
  if (requests.paths().empty())
    return true;
  return checkPictureSupport(error);
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
