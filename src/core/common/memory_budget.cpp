#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>

#include <unistd.h>

#include <cstdio>

namespace visfeat {

std::uint64_t
physicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0)
    return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

std::uint64_t
defaultMemoryLimitBytes()
{
  const std::uint64_t physical = physicalMemoryBytes();
  return physical > 0 ? physical / 4 * 3 : (std::uint64_t{8} << 30);
}

std::string
formatBytes(std::uint64_t bytes)
{
  char text[64];
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024.0 * 1024.0)
    std::snprintf(text, sizeof(text), "%.1f GiB", b / (1024.0 * 1024.0 * 1024.0));
  else
    std::snprintf(text, sizeof(text), "%.1f MiB", b / (1024.0 * 1024.0));
  return text;
}

void
checkMemory(std::uint64_t estimate_bytes,
            std::uint64_t limit_bytes,
            const std::string& what)
{
  const std::uint64_t limit = limit_bytes > 0 ? limit_bytes : defaultMemoryLimitBytes();
  if (estimate_bytes > limit)
    throw Error(what + " needs about " + formatBytes(estimate_bytes) +
                ", more than the limit of " + formatBytes(limit) +
                ": lower the resolution or raise the memory limit");
}

} // namespace visfeat
