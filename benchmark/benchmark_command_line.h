// The benchmarks' small command-line helpers.
#ifndef GEODESIC_SKELETON_BENCHMARK_COMMAND_LINE_H
#define GEODESIC_SKELETON_BENCHMARK_COMMAND_LINE_H

#include <sstream>
#include <string>
#include <vector>

// "a,b,c" -> {"a", "b", "c"}: the list of an option such as --meshes.
inline std::vector<std::string> split_commas(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  for(std::string item; std::getline(in, item, ',');)
    out.push_back(item);
  return out;
}

#endif // GEODESIC_SKELETON_BENCHMARK_COMMAND_LINE_H
