#include <visfeat/core/common/error.h>
#include <visfeat/core/mesh/mesh_sampling.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>

namespace visfeat {

double
triangleArea(const Eigen::Vector3d& a,
             const Eigen::Vector3d& b,
             const Eigen::Vector3d& c)
{
  return 0.5 * (b - a).cross(c - a).norm();
}

void
validateMesh(const SurfaceMesh& mesh)
{
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite())
      throw Error("mesh vertex " + std::to_string(v) +
                  " has a NaN or infinite coordinate");
  const std::size_t n = mesh.vertices.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t index : mesh.triangles[t])
      if (index >= n)
        throw Error("mesh triangle " + std::to_string(t) + " refers to vertex " +
                    std::to_string(index) + " of " + std::to_string(n));
}

double
meshArea(const SurfaceMesh& mesh)
{
  double total = 0.0;
  for (const auto& t : mesh.triangles)
    total +=
      triangleArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  return total;
}

bool
meshIsClosed(const SurfaceMesh& mesh)
{
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = t[i], b = t[(i + 1) % 3];
      edges.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  }
  if (edges.empty())
    return false;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    if (j - i < 2)
      return false;
    i = j;
  }
  return true;
}

std::size_t
samplesForSpacing(double area, double spacing, std::size_t max_count)
{
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw Error("the sampling spacing must be positive and finite");
  if (!(area > 0.0) || !std::isfinite(area))
    throw Error("the mesh has no area to sample");
  const double count = std::ceil(area / (spacing * spacing));
  if (!(count <= static_cast<double>(max_count))) {
    std::ostringstream s;
    s << "spacing " << spacing << " over area " << area << " gives " << count
      << " points, more than " << max_count;
    throw Error(s.str());
  }
  return static_cast<std::size_t>(count);
}

namespace {

/** \brief A double in [0, 1) from the top 53 bits: the same on every platform. */
double
unitReal(std::mt19937_64& rng)
{
  return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}

} // namespace

std::vector<MeshSample>
sampleMesh(const SurfaceMesh& mesh, std::size_t count, std::uint64_t seed)
{
  validateMesh(mesh);
  if (mesh.triangles.empty())
    throw Error("the mesh has no triangles");
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    total +=
      triangleArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    cumulative.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total))
    throw Error("the mesh has zero area (all " + std::to_string(mesh.triangles.size()) +
                " triangles are degenerate)");

  std::mt19937_64 rng(seed);
  std::vector<MeshSample> samples(count);
  for (MeshSample& s : samples) {
    // The first triangle whose cumulative area exceeds the pick: a zero-area triangle
    // repeats its predecessor's sum and can never be first to exceed it.
    const double pick = unitReal(rng) * total;
    const std::size_t t = std::min<std::size_t>(
      static_cast<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
        cumulative.begin()),
      cumulative.size() - 1);
    const double r1 = std::sqrt(unitReal(rng));
    const double r2 = unitReal(rng);
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d p = (1.0 - r1) * mesh.vertices[tri[0]] +
                              r1 * (1.0 - r2) * mesh.vertices[tri[1]] +
                              r1 * r2 * mesh.vertices[tri[2]];
    s.position = p.cast<float>();
    s.triangle = static_cast<std::uint32_t>(t);
  }
  return samples;
}

namespace {

/** \brief Line-oriented tokenizer of an OFF file: comments and blank lines skipped. */
class OffLines
{
public:
  explicit OffLines(std::istream& in)
      : in_(in)
  {}

  /** \brief The next non-blank line's tokens; false at the end of the file. */
  bool next(std::vector<std::string>& tokens)
  {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      std::istringstream words(line);
      tokens.clear();
      for (std::string w; words >> w;)
        tokens.push_back(w);
      if (!tokens.empty())
        return true;
    }
    if (in_.bad())
      throw Error("OFF: read error after line " + std::to_string(number_));
    return false;
  }

  std::size_t number() const { return number_; }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Error("OFF line " + std::to_string(number_) + ": " + what);
  }

private:
  std::istream& in_;
  std::size_t number_ = 0;
};

bool
parseCount(const std::string& text, unsigned long long& value)
{
  if (text.empty() || text[0] == '-' || text[0] == '+')
    return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtoull(text.c_str(), &end, 10);
  return errno == 0 && end != text.c_str() && *end == '\0';
}

bool
parseCoordinate(const std::string& text, double& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end != text.c_str() && *end == '\0';
}

} // namespace

SurfaceMesh
readOff(std::istream& in)
{
  OffLines lines(in);
  std::vector<std::string> tokens;
  if (!lines.next(tokens))
    throw Error("OFF: the file is empty");
  if (tokens[0] != "OFF")
    lines.fail("not an OFF file (expected the header 'OFF', got '" +
               tokens[0].substr(0, 20) + "')");
  tokens.erase(tokens.begin());
  if (tokens.empty() && !lines.next(tokens))
    throw Error("OFF: the file ends after its header (no vertex and face counts)");
  unsigned long long nv = 0, nf = 0, ne = 0;
  if (tokens.size() != 3 || !parseCount(tokens[0], nv) || !parseCount(tokens[1], nf) ||
      !parseCount(tokens[2], ne))
    lines.fail("expected the counts 'vertices faces edges'");
  constexpr unsigned long long kMaxCount = std::numeric_limits<std::uint32_t>::max();
  if (nv > kMaxCount || nf > kMaxCount)
    lines.fail("counts too large (" + std::to_string(nv) + " vertices, " +
               std::to_string(nf) + " faces)");

  SurfaceMesh mesh;
  // Counts come from the file: reserve no more than a plausible amount up front.
  mesh.vertices.reserve(static_cast<std::size_t>(std::min(nv, 1ULL << 20)));
  for (unsigned long long v = 0; v < nv; ++v) {
    if (!lines.next(tokens))
      throw Error("OFF: the file ends after " + std::to_string(v) + " of " +
                  std::to_string(nv) + " vertices");
    Eigen::Vector3d p;
    if (tokens.size() != 3 || !parseCoordinate(tokens[0], p.x()) ||
        !parseCoordinate(tokens[1], p.y()) || !parseCoordinate(tokens[2], p.z()))
      lines.fail("vertex " + std::to_string(v) + ": expected 'x y z'");
    if (!p.allFinite())
      lines.fail("vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
    mesh.vertices.push_back(p);
  }
  mesh.triangles.reserve(static_cast<std::size_t>(std::min(nf, 1ULL << 20)));
  std::vector<std::uint32_t> polygon;
  for (unsigned long long f = 0; f < nf; ++f) {
    if (!lines.next(tokens))
      throw Error("OFF: the file ends after " + std::to_string(f) + " of " +
                  std::to_string(nf) + " faces");
    unsigned long long n = 0;
    if (!parseCount(tokens[0], n) || n < 3)
      lines.fail("face " + std::to_string(f) + ": expected a vertex count >= 3, got '" +
                 tokens[0].substr(0, 20) + "'");
    // After the indices, up to 4 colour values are allowed. (n + 1 wrapped to 0 for
    // n = 2^64 - 1, and the indices were read past the tokens.)
    const unsigned long long given = tokens.size() - 1;
    if (given < n || given - n > 4)
      lines.fail("face " + std::to_string(f) + ": expected " + std::to_string(n) +
                 " vertex indices");
    polygon.clear();
    for (unsigned long long i = 1; i <= n; ++i) {
      unsigned long long index = 0;
      if (!parseCount(tokens[i], index))
        lines.fail("face " + std::to_string(f) + ": bad vertex index '" +
                   tokens[i].substr(0, 20) + "'");
      if (index >= nv)
        lines.fail("face " + std::to_string(f) + ": vertex index " +
                   std::to_string(index) + " out of range (" + std::to_string(nv) +
                   " vertices)");
      polygon.push_back(static_cast<std::uint32_t>(index));
    }
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
      mesh.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
  if (lines.next(tokens))
    lines.fail("unexpected data after the last face");
  return mesh;
}

} // namespace visfeat
