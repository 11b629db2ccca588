// Anchor harness: loads a native .gmap file (docs/FORMATS.md) into CGAL's Generalized_map<D>
// and times, in one process, the kernel operations that benches/cells.rs measures for gmap.
// Build: g++ -O3 -DNDEBUG -DCGAL_NDEBUG -std=c++17 -DGDIM=3 cgal_gmap_bench.cpp -o cgal_gmap_bench3
// Run:   ./cgal_gmap_bench3 file.gmap [reps]      (or simply benches/anchors/run-cgal.sh file.gmap)
#include <CGAL/Generalized_map.h>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#ifndef GDIM
#define GDIM 3
#endif
typedef CGAL::Generalized_map<GDIM> GMap;
typedef GMap::Dart_handle DH;

static double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int main(int argc, char** argv) {
  if (argc < 2) { std::cerr << "usage: gmap_bench file.gmap [reps]\n"; return 2; }
  int reps = argc > 2 ? atoi(argv[2]) : 5;
  std::ifstream in(argv[1]);
  std::string tag; unsigned n; size_t N;
  in >> tag >> n >> N;
  if (n != GDIM) { std::cerr << "dimension " << n << " but built for " << GDIM << "\n"; return 2; }
  std::vector<unsigned> a((size_t)(n + 1) * N);
  for (size_t i = 0; i < a.size(); ++i) in >> a[i];

  double t0 = now();
  GMap g;
  std::vector<DH> h(N);
  for (size_t d = 0; d < N; ++d) h[d] = g.create_dart();
  for (size_t d = 0; d < N; ++d)
    for (unsigned i = 0; i <= n; ++i) {
      size_t e = a[d * (n + 1) + i];
      if (e > d) g.basic_link_alpha(h[d], h[e], i);
    }
  double t_build = now() - t0;

  std::vector<unsigned> cells;
  double best_count = 1e9;
  for (int r = 0; r < reps; ++r) {
    t0 = now();
    cells = g.count_all_cells();
    best_count = std::min(best_count, now() - t0);
  }
  t0 = now();
  bool valid = g.is_valid();
  double t_valid = now() - t0;
  double best_orient = 1e9; bool orient = false;
  for (int r = 0; r < reps; ++r) {
    t0 = now();
    orient = g.is_orientable();
    best_orient = std::min(best_orient, now() - t0);
  }
  // unsew/sew every alpha_DIM link once (the grid's gluing), a topological editing workload
  std::vector<std::pair<DH, DH>> links;
  for (size_t d = 0; d < N; ++d) {
    size_t e = a[d * (n + 1) + n];
    if (e > d) links.push_back({h[d], h[e]});
  }
  t0 = now();
  for (auto& l : links) g.unlink_alpha(l.first, GDIM);
  for (auto& l : links) g.basic_link_alpha(l.first, l.second, GDIM);
  double t_relink = now() - t0;

  printf("{\"engine\":\"CGAL Generalized_map %d\",\"darts\":%zu,\"cells\":[", GDIM, N);
  for (unsigned i = 0; i <= n; ++i) printf("%s%u", i ? "," : "", cells[i]);
  printf("],\"components\":%u,\"valid\":%s,\"orientable\":%s,", cells[n + 1], valid ? "true" : "false",
         orient ? "true" : "false");
  printf("\"build_s\":%.4f,\"count_all_cells_s\":%.4f,\"is_valid_s\":%.4f,\"is_orientable_s\":%.4f,"
         "\"relink_top_s\":%.4f}\n",
         t_build, best_count, t_valid, best_orient, t_relink);
  return 0;
}
