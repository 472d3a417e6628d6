// Command-line arguments of the visfeat tools (not installed, not public API): strict
// number parsing, comma-separated lists, and the command line split into positional
// arguments, options with a value and switches.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace visfeat_tools {

/** \brief The extension of a path, lower case, with its dot ("" when none). */
std::string lowerExtension(const std::string& path);

/** \brief Strict integer parse: the whole string, base 10, no overflow, no leading
 * space. `value` is untouched on failure. */
bool parseInteger(const std::string& text, long long& value);

/** \brief Strict real parse: the whole string, finite, no leading space. `value` is
 * untouched on failure. */
bool parseReal(const std::string& text, double& value);

/** \brief "a,b,c" -> {"a", "b", "c"} (empty items kept, so "a,,b" can be refused). */
std::vector<std::string> splitList(const std::string& text);

/** \brief The command line split into positional arguments, options with a value and
 * switches, refusing unknown options and options without their value.
 *
 * pcl::console::parse_argument() returns -1 alike for an absent option, a missing
 * value and a value that is not a number (and strtoul takes "-1" for 4294967295), so
 * the tools parse the values themselves and say what is wrong. When an option is
 * repeated the last value wins. An argument that starts with '-' followed by a digit
 * or '.' is a positional argument (a negative number), not an option. */
class Arguments
{
public:
  Arguments(int argc,
            char** argv,
            const std::set<std::string>& value_options,
            const std::set<std::string>& switches);

  bool ok() const { return error_.empty(); }

  /** \brief Why the command line was refused ("" when ok()). */
  const std::string& error() const { return error_; }

  const std::vector<std::string>& positional() const { return positional_; }

  /** \brief True when the option or switch was given. */
  bool has(const std::string& name) const;

  /** \brief The raw value of an option, or "" when absent. */
  std::string value(const std::string& name) const;

  /** \brief Integer option in [min, max]; untouched when absent. False + message on a
   * bad value. */
  template <typename Int>
  bool getInteger(const std::string& name,
                  long long min,
                  long long max,
                  Int& out,
                  std::string& error) const
  {
    const auto it = values_.find(name);
    if (it == values_.end())
      return true;
    long long v = 0;
    if (!parseInteger(it->second, v)) {
      error = name + " expects an integer, got '" + it->second + "'";
      return false;
    }
    if (v < min || v > max) {
      error = name + " must be in [" + std::to_string(min) + ", " +
              std::to_string(max) + "], got " + it->second;
      return false;
    }
    out = static_cast<Int>(v);
    return true;
  }

  /** \brief Real option in [min, max]; untouched when absent. False + message on a bad
   * value. */
  bool getReal(const std::string& name,
               double min,
               double max,
               double& out,
               std::string& error) const;

private:
  std::map<std::string, std::string> values_;
  std::set<std::string> switches_;
  std::vector<std::string> positional_;
  std::string error_;
};

} // namespace visfeat_tools
