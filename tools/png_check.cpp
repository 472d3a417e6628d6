// visfeat_png_check: test helper for the tools_png ctest (not installed). Reads a PNG
// written by `visfeat -png` / `-png_radius` and checks that it shows something:
//   visfeat_png_check picture.png classes|radius WIDTH HEIGHT
// - the size is WIDTH x HEIGHT;
// - the object covers at least 10% of the pixels (the background is white) and its
//   box on screen spans at least half the width or the height (the camera fits it);
//   the texts (title top left, legend bottom left, and in radius mode the scalar bar
//   on the right) are left out of these two measures;
// - classes: pixels of the vertex red, the edge blue and the face pastels are all
//   present (so the three classes are drawn distinguishably);
// - radius: saturated pixels of at least 4 of 12 hue bins, blue and red among them
//   (the ramp is used, not one colour).
// Prints the measurements; exit code 0 when all checks pass, 1 otherwise.

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Rgb
{
  int r, g, b;
};

bool
near(const Rgb& a, const Rgb& b, int tolerance)
{
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance;
}

/** \brief Hue in [0, 360) and saturation in [0, 1] of an RGB colour. */
void
hueSaturation(const Rgb& c, double& hue, double& saturation)
{
  const int hi = std::max({c.r, c.g, c.b});
  const int lo = std::min({c.r, c.g, c.b});
  saturation = hi == 0 ? 0.0 : static_cast<double>(hi - lo) / hi;
  if (hi == lo) {
    hue = 0.0;
    return;
  }
  const double d = hi - lo;
  if (hi == c.r)
    hue = 60.0 * std::fmod((c.g - c.b) / d + 6.0, 6.0);
  else if (hi == c.g)
    hue = 60.0 * ((c.b - c.r) / d + 2.0);
  else
    hue = 60.0 * ((c.r - c.g) / d + 4.0);
}

int
check(bool ok, const char* what)
{
  std::printf("  %-58s %s\n", what, ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}

} // namespace

int
main(int argc, char** argv)
{
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s picture.png classes|radius WIDTH HEIGHT\n",
                 argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  const std::string mode = argv[2];
  const int want_w = std::atoi(argv[3]);
  const int want_h = std::atoi(argv[4]);
  if (mode != "classes" && mode != "radius") {
    std::fprintf(stderr, "mode must be classes or radius\n");
    return 2;
  }

  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile(path.c_str())) {
    std::printf("%s: not a readable PNG\n", path.c_str());
    return 1;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  const int components = image->GetNumberOfScalarComponents();
  std::printf("%s: %dx%d, %d components, mode %s\n", path.c_str(), w, h, components,
              mode.c_str());
  int failures = check(w == want_w && h == want_h, "size as requested");
  if (components < 3 || w <= 0 || h <= 0)
    return 1;

  const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
  const Rgb vertex{220, 20, 30}, edge{25, 85, 235};
  long long object = 0, vertex_px = 0, edge_px = 0, face_px = 0;
  std::array<long long, 12> hue_bins{};
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p =
        pixels + (static_cast<long long>(y) * w + x) * components;
      const Rgb c{p[0], p[1], p[2]};
      if (c.r >= 245 && c.g >= 245 && c.b >= 245)
        continue;
      // Image rows run bottom-up in VTK: y = 0 is the bottom row.
      const bool text =
        y >= h - 40 || (y < 110 && x < 170) || (mode == "radius" && x >= w * 0.82);
      if (!text) {
        ++object;
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
      double hue = 0.0, saturation = 0.0;
      hueSaturation(c, hue, saturation);
      if (near(c, vertex, 40))
        ++vertex_px;
      else if (near(c, edge, 40))
        ++edge_px;
      else if (std::min({c.r, c.g, c.b}) >= 160 && saturation < 0.35)
        ++face_px; // light, unsaturated: the face pastels
      if (saturation > 0.6 && std::max({c.r, c.g, c.b}) > 150)
        ++hue_bins[static_cast<std::size_t>(hue / 30.0) % hue_bins.size()];
    }
  const double total = static_cast<double>(w) * h;
  const double cover = object / total;
  const double span = std::max(x1 >= x0 ? (x1 - x0 + 1.0) / w : 0.0,
                               y1 >= y0 ? (y1 - y0 + 1.0) / h : 0.0);
  std::printf("  object pixels %.1f%%, object box spans %.0f%% of the frame\n",
              100.0 * cover, 100.0 * span);
  failures += check(cover >= 0.10, "object covers >= 10% of the pixels");
  failures += check(span >= 0.5, "object spans >= 50% of the width or height");
  if (mode == "classes") {
    std::printf("  vertex red %.2f%%, edge blue %.2f%%, face pastel %.1f%%\n",
                100.0 * vertex_px / total, 100.0 * edge_px / total,
                100.0 * face_px / total);
    failures += check(vertex_px >= total * 0.0005, "vertex red >= 0.05% of the pixels");
    failures += check(edge_px >= total * 0.005, "edge blue >= 0.5% of the pixels");
    failures += check(face_px >= total * 0.05, "face pastels >= 5% of the pixels");
  } else {
    int bins = 0;
    std::printf("  saturated pixels per 30-degree hue bin:");
    for (long long n : hue_bins) {
      std::printf(" %lld", n);
      if (n >= total * 0.001)
        ++bins;
    }
    std::printf("\n");
    const bool red = hue_bins[0] + hue_bins[11] >= total * 0.001;
    const bool blue = hue_bins[7] + hue_bins[8] >= total * 0.001;
    failures += check(bins >= 4, "the ramp: >= 4 hue bins with >= 0.1% of the pixels");
    failures += check(red && blue, "both ends of the ramp (red and blue) present");
  }
  std::printf("%s\n", failures == 0 ? "all checks passed" : "some checks FAILED");
  return failures == 0 ? 0 : 1;
}
