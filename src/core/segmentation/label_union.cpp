#include "label_union.h"

#include <algorithm>
#include <numeric>

namespace visfeat {
namespace segmentation {

LabelUnion::LabelUnion(std::size_t labels)
    : parent_(labels + 1)
{
  std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
}

std::uint32_t
LabelUnion::find(std::uint32_t a)
{
  while (parent_[a] != a)
    a = parent_[a] = parent_[parent_[a]];
  return a;
}

void
LabelUnion::join(std::uint32_t a, std::uint32_t b)
{
  a = find(a);
  b = find(b);
  if (a != b)
    parent_[std::max(a, b)] = std::min(a, b);
}

void
LabelUnion::attach(std::uint32_t a, std::uint32_t b)
{
  a = find(a);
  b = find(b);
  if (a != b)
    parent_[b] = a;
}

LabelContacts::LabelContacts(const VoxelBand& band,
                             const std::vector<std::uint32_t>& labels)
{
  for (std::size_t c = 0; c < labels.size(); ++c) {
    const std::uint32_t a = labels[c];
    if (a == 0)
      continue;
    for (const CellId nb : band.neighbours(static_cast<CellId>(c))) {
      if (nb == kNoCell)
        continue;
      const std::uint32_t b = labels[static_cast<std::size_t>(nb)];
      if (b != 0 && a != b)
        ++by_label_[{a, b}];
    }
  }
}

Contacts
LabelContacts::through(LabelUnion& sets) const
{
  Contacts contacts;
  for (const auto& [pair, count] : by_label_) {
    const std::uint32_t a = sets.find(pair.first);
    const std::uint32_t b = sets.find(pair.second);
    if (a != b)
      contacts[{a, b}] += count;
  }
  return contacts;
}

} // namespace segmentation
} // namespace visfeat
