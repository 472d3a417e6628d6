#pragma once

#include <cstdint>
#include <string>

namespace visfeat {

/** \brief Physical memory of this machine in bytes (0 when it cannot be read). */
std::uint64_t physicalMemoryBytes();

/** \brief The default limit for one computation: 3/4 of physical memory
 * (8 GiB when physical memory cannot be read). */
std::uint64_t defaultMemoryLimitBytes();

/** \brief Refuse, before allocating, work whose estimate exceeds the limit.
 * \param[in] estimate_bytes what the step will allocate
 * \param[in] limit_bytes the budget (0 = defaultMemoryLimitBytes())
 * \param[in] what a short description for the message, e.g. "a 4096^3 grid"
 * \throws visfeat::Error naming both figures in MiB and how to get below the limit.
 */
void checkMemory(std::uint64_t estimate_bytes,
                 std::uint64_t limit_bytes,
                 const std::string& what);

/** \brief "123.4 MiB" */
std::string formatBytes(std::uint64_t bytes);

} // namespace visfeat
