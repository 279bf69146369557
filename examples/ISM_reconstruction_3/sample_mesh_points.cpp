// Samples points, WITHOUT normals, on a closed triangle mesh: area-weighted, with a
// fixed seed, optionally with Gaussian noise. Makes inputs with a known answer for
// ism_reconstruct (the mesh is the ground truth).
//
// Usage: sample_mesh_points [--seed S] [--noise SIGMA] MESH N OUTPUT.xyz
//   --noise is the standard deviation of the noise per coordinate, as a fraction of the
//   diagonal of the mesh's bounding box (default 0: points on the surface).

#include "ism_evaluation.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace {

void usage(std::ostream& os)
{
  os << "Usage: sample_mesh_points [--seed S] [--noise SIGMA] MESH N OUTPUT.xyz\n"
        "  Writes N points sampled uniformly by area on MESH (no normals), one 'x y z' per line.\n"
        "  --seed S       random seed (default 1)\n"
        "  --noise SIGMA  Gaussian noise per coordinate, as a fraction of the bounding box\n"
        "                 diagonal (default 0)\n";
}

bool parse_double(const char* s, double& v)
{
  char* end = nullptr;
  errno = 0;
  v = std::strtod(s, &end);
  return end != s && *end == '\0' && errno == 0 && std::isfinite(v);
}

bool parse_unsigned(const char* s, unsigned long long& v)
{
  if(*s == '-' || *s == '\0') return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtoull(s, &end, 10);
  return *end == '\0' && errno == 0;
}

} // namespace

int main(int argc, char** argv)
{
  unsigned long long seed = 1;
  double noise = 0;
  std::vector<std::string> positional;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "-h" || a == "--help") { usage(std::cout); return 0; }
    if(a == "--seed" || a == "--noise")
    {
      if(i + 1 >= argc) { std::cerr << "error: " << a << " needs a value\n"; return 2; }
      const char* v = argv[++i];
      if(a == "--seed" ? !parse_unsigned(v, seed) : !(parse_double(v, noise) && noise >= 0))
      {
        std::cerr << "error: bad value '" << v << "' for " << a << "\n";
        return 2;
      }
    }
    else if(a.size() > 1 && a[0] == '-')
    {
      std::cerr << "error: unknown option " << a << "\n";
      usage(std::cerr);
      return 2;
    }
    else
      positional.push_back(a);
  }
  unsigned long long n = 0;
  if(positional.size() != 3 || !parse_unsigned(positional[1].c_str(), n) || n == 0)
  {
    usage(std::cerr);
    return 2;
  }

  ISM_eval::Mesh mesh;
  if(!ISM_eval::read_mesh(positional[0], mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from '" << positional[0] << "'\n";
    return 1;
  }
  const double sigma = noise * ISM_eval::diagonal(ISM_eval::bbox(mesh));
  const auto samples = ISM_eval::sample_points(mesh, std::size_t(n), unsigned(seed), sigma);

  // write to a temporary file beside the output, then rename: never a half-written file
  const std::string out = positional[2], tmp = out + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream os(tmp);
    os.precision(17);
    for(const auto& s : samples)
      os << s.first.x() << ' ' << s.first.y() << ' ' << s.first.z() << '\n';
    if(!os.flush())
    {
      std::remove(tmp.c_str());
      std::cerr << "error: cannot write '" << out << "'\n";
      return 1;
    }
  }
  if(std::rename(tmp.c_str(), out.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    std::cerr << "error: cannot write '" << out << "'\n";
    return 1;
  }
  std::cout << "wrote " << samples.size() << " points sampled on " << positional[0] << " to " << out << "\n";
  return 0;
}
