// How many cores this process may run on: its affinity mask (a container's or taskset's limit),
// not the machine's count, for the commands that size their threads or worker processes by it.
#pragma once

namespace urdfsnap {

// The cores in this process's affinity mask (sched_getaffinity), else the hardware's count; at
// least 1.
int UsableCores();

}  // namespace urdfsnap
