// Anchor harness: a tetrahedral mesh made into CGAL's linear cell complex as a mesh reader
// would, the way the figures were taken: every tetrahedron made on its own with its
// four corner points (make_tetrahedron), then sew3_same_facets() finds the faces to 3-sew by
// their points. The tetrahedra come from a plain text file (written by tetgrid.py): the
// point count, one point `x y z` a line, the tetrahedron count, four point indices a line.
// Prints one JSON line: seconds to read the file, to make the tetrahedra and to sew them (wall
// clock and this thread's CPU time), the darts, the cell counts and the number of vertex
// points left (checked untimed), and the peak resident memory (VmHWM, what /usr/bin/time -v
// reports).
// Two variants (second argument): `gmap` (default), Linear_cell_complex_for_generalized_map<3>,
// the issue's; `cmap`, Linear_cell_complex_for_combinatorial_map<3> (12 darts a tetrahedron,
// not 24). CGAL 5.5's sew3_same_facets on the generalized map sews only the pairs of faces whose
// darts at the smallest point it happens to pick with opposite orientations: on the
// tetrahedral grid it leaves about half the inner faces unsewn (the cell counts say so), so
// only the combinatorial map does the same work as gmap (every inner face sewn).
// Build: g++ -O3 -DNDEBUG -DCGAL_NDEBUG -std=c++17 cgal_mesh_tets.cpp -o cgal_mesh_tets -lgmp -lmpfr
// Run:   ./cgal_mesh_tets FILE.txt [gmap|cmap]   (or benches/anchors/run-cgal-mesh.sh K)
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_for_generalized_map.h>
#include <cstring>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

static double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

static double cpu_now() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static long peak_rss_kb() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  long kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmHWM: %ld kB", &kb) == 1) break;
  std::fclose(f);
  return kb;
}

using Point = CGAL::Linear_cell_complex_traits<3>::Point;

template <class LCC>
int run(const std::vector<Point>& pts, const std::vector<long>& tets, long nt, double w0, double c0, double w1,
        double c1, const char* variant);

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE.txt\n", argv[0]);
    return 2;
  }
  double w0 = now(), c0 = cpu_now();
  FILE* f = std::fopen(argv[1], "r");
  if (!f) {
    std::perror(argv[1]);
    return 1;
  }
  long np = 0, nt = 0;
  if (std::fscanf(f, "%ld", &np) != 1) return 1;
  std::vector<Point> pts;
  pts.reserve(np);
  for (long i = 0; i < np; ++i) {
    double x, y, z;
    if (std::fscanf(f, "%lf %lf %lf", &x, &y, &z) != 3) return 1;
    pts.emplace_back(x, y, z);
  }
  if (std::fscanf(f, "%ld", &nt) != 1) return 1;
  std::vector<long> tets(4 * nt);
  for (long i = 0; i < 4 * nt; ++i)
    if (std::fscanf(f, "%ld", &tets[i]) != 1) return 1;
  std::fclose(f);
  double w1 = now(), c1 = cpu_now();
  bool cmap = argc > 2 && std::strcmp(argv[2], "cmap") == 0;
  return cmap ? run<CGAL::Linear_cell_complex_for_combinatorial_map<3>>(pts, tets, nt, w0, c0, w1, c1, "cmap")
              : run<CGAL::Linear_cell_complex_for_generalized_map<3>>(pts, tets, nt, w0, c0, w1, c1, "gmap");
}

template <class LCC>
int run(const std::vector<Point>& pts, const std::vector<long>& tets, long nt, double w0, double c0, double w1,
        double c1, const char* variant) {
  LCC lcc;
  for (long t = 0; t < nt; ++t)
    lcc.make_tetrahedron(pts[tets[4 * t]], pts[tets[4 * t + 1]], pts[tets[4 * t + 2]], pts[tets[4 * t + 3]]);
  double w2 = now(), c2 = cpu_now();
  lcc.sew3_same_facets();
  double w3 = now(), c3 = cpu_now();
  long peak = peak_rss_kb();
  std::vector<unsigned int> cells = {0, 1, 2, 3};
  std::vector<unsigned int> res = lcc.count_cells(cells);
  std::printf(
      "{\"variant\": \"%s\", \"tetrahedra\": %ld, \"darts\": %zu, \"cells\": [%u, %u, %u, %u], \"vertex_points\": %zu, "
      "\"read_s\": %.3f, \"make_s\": %.3f, \"sew_s\": %.3f, \"cpu_read_s\": %.3f, \"cpu_make_s\": %.3f, "
      "\"cpu_sew_s\": %.3f, \"peak_rss_kb\": %ld}\n",
      variant, nt, lcc.number_of_darts(), res[0], res[1], res[2], res[3], lcc.number_of_vertex_attributes(), w1 - w0,
      w2 - w1, w3 - w2, c1 - c0, c2 - c1, c3 - c2, peak);
  return 0;
}
