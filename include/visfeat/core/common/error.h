#pragma once

#include <stdexcept>
#include <string>

namespace visfeat {

/** \brief What every visfeat core function throws on bad input or parameters.
 *
 * The message names the problem in one line (no trailing newline), so that a tool
 * can print it as is; the `pcl::Feature` front class turns it into a `PCL_ERROR`.
 */
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& what)
      : std::runtime_error(what)
  {}
};

} // namespace visfeat
