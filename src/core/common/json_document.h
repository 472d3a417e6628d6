// Private to visfeat's sources (not installed): how every JSON file visfeat writes is
// produced. nlohmann-json (Debian's nlohmann-json3-dev, header-only) does the escaping
// and the number formatting: doubles are written so that they read back exactly, NaN
// and infinities as null.
#pragma once

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <ostream>

namespace visfeat {
namespace json_document {

/** \brief Objects keep their members in the order written. */
using Json = nlohmann::ordered_json;

/** \brief [x, y, z]; a NaN or infinite coordinate is written as null. */
inline Json
vector3(const Eigen::Vector3d& v)
{
  return Json::array({v.x(), v.y(), v.z()});
}

/** \brief The document, indented by 2 spaces, then a newline. Bytes that are not valid
 * UTF-8 (a file name in another encoding) are replaced by U+FFFD instead of failing. */
inline void
write(std::ostream& out, const Json& document)
{
  out << document.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

} // namespace json_document
} // namespace visfeat
