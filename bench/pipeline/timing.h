// What the pipeline benchmark's measurements share: wall-clock medians and running a process.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace urdfsnap::bench {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b);

double Median(std::vector<double> v);

// The CPU time of all of this process's threads so far, in seconds (on a shared machine the wall
// time grows with the load, the CPU time much less).
double CpuSeconds();

// Median wall time of `runs` calls of fn (each timed on its own), in seconds.
double MedianTime(int runs, const std::function<void()>& fn);

// Runs the program args[0] with args and this process's environment plus `environment`
// ("NAME=value" entries); returns whether it exited 0. Exits the benchmark when it cannot start.
bool TryProcess(std::vector<std::string> args, const std::vector<std::string>& environment = {});

// TryProcess, exiting the benchmark when the process fails.
void RunProcess(const std::vector<std::string>& args, const std::vector<std::string>& environment = {});

}  // namespace urdfsnap::bench
