// The small helpers that the benchmark programs share: command-line lists and medians.

#ifndef GEODESIC_SKELETON_BENCHMARK_COMMON_H
#define GEODESIC_SKELETON_BENCHMARK_COMMON_H

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace benchmark_common {

// "a,b,c" -> {"a", "b", "c"} (the --meshes option).
inline std::vector<std::string> split_commas(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  for(std::string item; std::getline(in, item, ',');)
    out.push_back(item);
  return out;
}

// The median (the upper one for an even count) of non-empty `v`.
inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The options that the benchmarks share; the defaults are what the caller puts in.
struct Options
{
  std::string data_dir;
  int repeats = 5;
  int resolution = 64;
  std::vector<std::string> names; // the demo meshes, without ".off"
  bool flag = false;              // the program's own switch (e.g. --no-mcf), when given
};

// The defaults: the animals and characters among the demo meshes, five runs.
inline Options default_options(const std::string& data_dir, int resolution)
{
  Options o;
  o.data_dir = data_dir;
  o.resolution = resolution;
  o.names = {"elephant", "cow", "triceratops", "dino", "homer", "bull", "camel", "bear", "man", "armadillo", "hand"};
  return o;
}

// Reads [DATA_DIR] [--repeats N] [--meshes a,b] [--resolution R] [FLAG] into `o`; prints the
// usage and returns false on anything else.
inline bool parse_options(int argc, char* argv[], const std::string& flag, Options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--repeats" && i + 1 < argc)
      o.repeats = std::max(1, std::atoi(argv[++i]));
    else if(arg == "--meshes" && i + 1 < argc)
      o.names = split_commas(argv[++i]);
    else if(arg == "--resolution" && i + 1 < argc)
      o.resolution = std::atoi(argv[++i]);
    else if(arg == flag)
      o.flag = true;
    else if(!arg.empty() && arg[0] != '-')
      o.data_dir = arg;
    else
    {
      std::cout << "usage: " << argv[0] << " [DATA_DIR] [--repeats N] [--meshes a,b] [--resolution R] [" << flag
                << "]\n";
      return false;
    }
  }
  return true;
}

} // namespace benchmark_common

#endif // GEODESIC_SKELETON_BENCHMARK_COMMON_H
