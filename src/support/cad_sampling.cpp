#include <support/cad_frames.h>
#include <support/cad_queries.h>
#include <support/cad_sampling.h>
#include <support/portable_random.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>

namespace visfeat {
namespace synthetic {

using detail::CylinderFrame;
using detail::cylinderFrame;
using detail::kPi;
using detail::PlanarFrame;
using detail::planarFrame;
using detail::Point2;

double
cellSize(const CadModel& model, int resolution)
{
  if (resolution <= 0)
    throw Error("cellSize: the resolution must be positive, got " +
                std::to_string(resolution));
  return model.bounds().sizes().maxCoeff() / resolution;
}

std::size_t
samplesForSpacing(const CadModel& model, int resolution, double spacing_cells)
{
  if (!(spacing_cells > 0.0) || !std::isfinite(spacing_cells))
    throw Error("samplesForSpacing: the spacing must be positive and finite");
  const double spacing = spacing_cells * cellSize(model, resolution);
  return static_cast<std::size_t>(std::ceil(model.area() / (spacing * spacing)));
}

namespace {

/** The faces' areas, accumulated in face order. */
std::vector<double>
cumulativeFaceAreas(const CadModel& model)
{
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    total += faceArea(model, static_cast<int>(f));
    cumulative.push_back(total);
  }
  return cumulative;
}

/** The faces' areas times their density multipliers, accumulated in face order. */
std::vector<double>
cumulativeFaceWeights(const CadModel& model, const std::vector<double>& density)
{
  if (density.size() != model.faces.size())
    throw Error("sampleCadModel: face_density has " + std::to_string(density.size()) +
                " values for " + std::to_string(model.faces.size()) + " faces");
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    if (!(density[f] >= 0.0) || !std::isfinite(density[f]))
      throw Error("sampleCadModel: face_density[" + std::to_string(f) +
                  "] must be finite and >= 0");
    total += faceArea(model, static_cast<int>(f)) * density[f];
    cumulative.push_back(total);
  }
  if (!(total > 0.0))
    throw Error("sampleCadModel: face_density is zero on every face");
  return cumulative;
}

/** options.count, or else the count of options.spacing over the total area. */
std::size_t
sampleCount(const SamplingOptions& options, double total)
{
  std::size_t count = options.count;
  if (count == 0) {
    if (!(options.spacing > 0.0) || !std::isfinite(options.spacing))
      throw Error("sampleCadModel: give a count or a positive spacing");
    const double n = std::ceil(total / (options.spacing * options.spacing));
    if (!(n < 1e12))
      throw Error("sampleCadModel: the spacing gives too many points");
    count = static_cast<std::size_t>(n);
  }
  return count;
}

/** Draws uniform points on the faces of a model: the frame of each face (planar or
 * cylindrical, as its kind), and its accumulated area to pick it by. */
class FaceSampler
{
public:
  FaceSampler(const CadModel& model, std::vector<double> cumulative)
      : model_(model)
      , cumulative_(std::move(cumulative))
      , planes_(model.faces.size())
      , cylinders_(model.faces.size())
  {
    for (std::size_t f = 0; f < model.faces.size(); ++f) {
      if (model.faces[f].kind == CadFace::Kind::kPlanar)
        planes_[f] = planarFrame(model, model.faces[f]);
      else
        cylinders_[f] = cylinderFrame(model, model.faces[f]);
    }
  }

  /** A face with probability proportional to its weight (its area, or its area times
   * its density). */
  std::size_t pickFace(std::mt19937_64& rng) const
  {
    const double pick = unit_(rng) * cumulative_.back();
    std::size_t f = std::min<std::size_t>(
      static_cast<std::size_t>(
        std::lower_bound(cumulative_.begin(), cumulative_.end(), pick) -
        cumulative_.begin()),
      model_.faces.size() - 1);
    // A pick of exactly 0 may land on leading faces of weight 0: skip them.
    while (f + 1 < cumulative_.size() && !(cumulative_[f] > 0.0))
      ++f;
    return f;
  }

  /** A uniform point on face f: a cylinder by (angle, height), a planar face by
   * rejection in its bounding rectangle. */
  Eigen::Vector3d pointOn(std::size_t f, std::mt19937_64& rng) const
  {
    if (model_.faces[f].kind == CadFace::Kind::kCylindrical) {
      const CylinderFrame& c = cylinders_[f];
      const double angle = 2.0 * kPi * unit_(rng);
      const double t = c.height * unit_(rng);
      return c.base + t * c.axis +
             c.radius * (std::cos(angle) * c.e1 + std::sin(angle) * c.e2);
    }
    constexpr int kMaxRejections = 1000000;
    const PlanarFrame& plane = planes_[f];
    Point2 q;
    int tries = 0;
    do {
      if (++tries > kMaxRejections)
        throw Error("sampleCadModel: face " + std::to_string(f) + " of model '" +
                    model_.name + "' rejects every sample");
      q.x = plane.lo.x + (plane.hi.x - plane.lo.x) * unit_(rng);
      q.y = plane.lo.y + (plane.hi.y - plane.lo.y) * unit_(rng);
    } while (!plane.contains(q));
    return plane.lift(q);
  }

private:
  const CadModel& model_;
  std::vector<double> cumulative_;
  std::vector<PlanarFrame> planes_;
  std::vector<CylinderFrame> cylinders_;
  UniformReal unit_{0.0, 1.0};
};

} // namespace

std::vector<double>
denseFace(const CadModel& model, int dense_face, double ratio)
{
  if (dense_face < 0 || dense_face >= static_cast<int>(model.faces.size()))
    throw Error("denseFace: face " + std::to_string(dense_face) +
                " is not a face of '" + model.name + "' (0 to " +
                std::to_string(model.faces.size() - 1) + ")");
  if (!(ratio > 0.0) || !std::isfinite(ratio))
    throw Error("denseFace: the density ratio must be positive and finite");
  std::vector<double> density(model.faces.size(), 1.0);
  density[static_cast<std::size_t>(dense_face)] = ratio;
  return density;
}

CadSamples
sampleCadModel(const CadModel& model, const SamplingOptions& options)
{
  if (!(options.noise_sigma >= 0.0) || !std::isfinite(options.noise_sigma))
    throw Error("sampleCadModel: the noise sigma must be finite and >= 0");
  if (!options.rotation.allFinite())
    throw Error("sampleCadModel: the rotation is not finite");
  std::vector<double> cumulative = cumulativeFaceAreas(model);
  const double total = cumulative.empty() ? 0.0 : cumulative.back();
  if (!(total > 0.0))
    throw Error("sampleCadModel: model '" + model.name + "' has no area");
  const std::size_t count = sampleCount(options, total);
  if (!options.face_density.empty())
    cumulative = cumulativeFaceWeights(model, options.face_density);
  const FaceSampler sampler(model, std::move(cumulative));

  std::mt19937_64 rng(options.seed);
  std::mt19937_64 noise_rng(options.seed ^ 0x9E3779B97F4A7C15ull); // a stream apart
  Normal gauss(0.0, options.noise_sigma > 0.0 ? options.noise_sigma : 1.0);
  CadSamples out;
  out.points.reserve(count);
  out.face.reserve(count);
  out.curve_distance.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t f = sampler.pickFace(rng);
    const Eigen::Vector3d p = sampler.pointOn(f, rng);
    out.curve_distance.push_back(curveDistance(model, p));
    out.face.push_back(static_cast<int>(f));
    Eigen::Vector3d x = options.rotation * p;
    if (options.noise_sigma > 0.0)
      x += Eigen::Vector3d(gauss(noise_rng), gauss(noise_rng), gauss(noise_rng));
    out.points.push_back(x.cast<float>());
  }
  return out;
}

} // namespace synthetic
} // namespace visfeat
