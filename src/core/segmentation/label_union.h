#pragma once

// Internal to the segmentation (not installed): merging labels into sets, and the
// boundary the sets share.

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace visfeat {
namespace segmentation {

/** \brief Union-find over labels 1..n (0 unused). Only the roots matter: which label
 * is a set's root depends on the calls, never on the order of find() calls. */
class LabelUnion
{
public:
  explicit LabelUnion(std::size_t labels);

  /** \brief The root of a's set. */
  std::uint32_t find(std::uint32_t a);

  /** \brief Joins b's set and a's; the smaller root survives, so results do not depend
   * on the order of calls. */
  void join(std::uint32_t a, std::uint32_t b);

  /** \brief Puts b's set under a's root (a merge into a, which keeps its class). */
  void attach(std::uint32_t a, std::uint32_t b);

private:
  std::vector<std::uint32_t> parent_;
};

/** \brief Shared boundary between labels or sets: (a, b) -> the number of 6-adjacent
 * cell pairs with one cell in a and one in b, stored both ways ((a, b) and (b, a)),
 * a != b. Ordered, so loops over it do not depend on how it was built. */
using Contacts = std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>;

/** \brief The contacts of a labeling of the band, counted once per label pair, then
 * read through a LabelUnion as the contacts of its sets.
 *
 * The cell labels stay fixed while the union merges them, so the contacts of the
 * sets are the label contacts summed by root: through() gives the same counts as a
 * scan of the band with every label replaced by its root, at the cost of the label
 * pairs rather than the cells.
 */
class LabelContacts
{
public:
  LabelContacts() = default;

  /** \brief Scans the band once. labels: per cell, its label (0 = none: no contact).
   */
  LabelContacts(const VoxelBand& band, const std::vector<std::uint32_t>& labels);

  /** \brief Contacts between labels. */
  const Contacts& byLabel() const { return by_label_; }

  /** \brief Contacts between the sets of `sets` (keys are roots). */
  Contacts through(LabelUnion& sets) const;

private:
  Contacts by_label_;
};

} // namespace segmentation
} // namespace visfeat
