// Command-line arguments of the visfeat tools; see arguments.h.

#include "common/arguments.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace visfeat_tools {

std::string
lowerExtension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool
parseInteger(const std::string& text, long long& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
    return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || end == text.c_str() || *end != '\0')
    return false;
  value = v;
  return true;
}

bool
parseReal(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
    return false;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (errno != 0 || end == text.c_str() || *end != '\0' || !std::isfinite(v))
    return false;
  value = v;
  return true;
}

std::vector<std::string>
splitList(const std::string& text)
{
  std::vector<std::string> items;
  std::string item;
  std::istringstream stream(text);
  while (std::getline(stream, item, ','))
    items.push_back(item);
  if (!text.empty() && text.back() == ',')
    items.emplace_back();
  return items;
}

Arguments::Arguments(int argc,
                     char** argv,
                     const std::set<std::string>& value_options,
                     const std::set<std::string>& switches)
{
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (value_options.count(arg)) {
      if (i + 1 >= argc) {
        error_ = "option " + arg + " needs a value";
        return;
      }
      values_[arg] = argv[++i];
    } else if (switches.count(arg)) {
      switches_.insert(arg);
    } else if (arg.size() > 1 && arg[0] == '-' &&
               !std::isdigit(static_cast<unsigned char>(arg[1])) && arg[1] != '.') {
      error_ = "unknown option " + arg + " (see -h)";
      return;
    } else {
      positional_.push_back(arg);
    }
  }
}

bool
Arguments::has(const std::string& name) const
{
  return values_.count(name) > 0 || switches_.count(name) > 0;
}

std::string
Arguments::value(const std::string& name) const
{
  const auto it = values_.find(name);
  return it == values_.end() ? std::string() : it->second;
}

bool
Arguments::getReal(const std::string& name,
                   double min,
                   double max,
                   double& out,
                   std::string& error) const
{
  const auto it = values_.find(name);
  if (it == values_.end())
    return true;
  double v = 0.0;
  if (!parseReal(it->second, v)) {
    error = name + " expects a number, got '" + it->second + "'";
    return false;
  }
  if (v < min || v > max) {
    std::ostringstream s;
    s << name << " must be in [" << min << ", " << max << "], got " << it->second;
    error = s.str();
    return false;
  }
  out = v;
  return true;
}

} // namespace visfeat_tools
