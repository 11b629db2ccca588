// Anchor harness: the K^3 hexahedral grid built cell by cell with CGAL, as a modelling kernel
// would: every hexahedron made on its own with its eight corner points, then each pair of
// neighbours 3-sewn (the sew merges the corner points that meet). Times, in one process:
//   gmap        Generalized_map<3>: make_combinatorial_hexahedron + sew<3>   (no attributes)
//   lcc         Linear_cell_complex_for_generalized_map<3>: make_hexahedron(points) + sew<3>
//   lcc_label   the same with an int 3-attribute (a label) created on every volume
//   same_facets the hexahedra with points left unsewn, then sew3_same_facets (faces found by
//               their points)
// Prints one JSON line per variant: the best of `reps` runs for building the hexahedra, for
// sewing them, and for both, in wall-clock time and in the thread's CPU time (cpu_*); plus the cell counts and the number of vertex attributes left
// (one per grid vertex when the sew merged the points correctly), checked once, untimed.
// Build: g++ -O3 -DNDEBUG -DCGAL_NDEBUG -std=c++17 cgal_lcc_grid.cpp -o cgal_lcc_grid -lgmp -lmpfr
// Run:   ./cgal_lcc_grid [K] [reps] [variant]   (or benches/anchors/run-cgal-lcc.sh [K] [reps] [variant]);
//        with a variant (plain, lcc, lcc_label, same_facets) only that one runs, and its
//        JSON line's peak_rss_kb is the peak resident memory of building it.
#include <CGAL/Generalized_map.h>
#include <CGAL/Linear_cell_complex_for_generalized_map.h>
#include <CGAL/Linear_cell_complex_traits.h>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <queue>
#include <string>
#include <vector>

static double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU time of this thread: on a shared machine, the time spent waiting for a core is not
// counted, so it is the steadier figure to compare with the Rust side (which reads the same
// clock from /proc/thread-self/schedstat).
static double cpu_now() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// The peak resident memory of this process so far, in kB (VmHWM of /proc/self/status, what
// /usr/bin/time -v reports); 0 where it cannot be read. Run with one variant (third
// argument), it is that variant's peak.
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

using Traits = CGAL::Linear_cell_complex_traits<3>;

// Items of an LCC whose vertices carry a point and whose volumes carry an int label.
struct LabelledItems {
  template <class L>
  struct Dart_wrapper {
    using Vertex = CGAL::Cell_attribute_with_point<L>;
    using Volume = CGAL::Cell_attribute<L, int>;
    using Attributes = std::tuple<Vertex, void, void, Volume>;
  };
};

using Plain = CGAL::Generalized_map<3>;
using Lcc = CGAL::Linear_cell_complex_for_generalized_map<3, 3, Traits>;
using LccLabel = CGAL::Linear_cell_complex_for_generalized_map<3, 3, Traits, LabelledItems>;

// A path of alpha indices from the dart a constructor returns to another dart of the same
// hexahedron. The constructors lay out every hexahedron the same way, so a path found once on
// a prototype (by its geometry) names the same dart in every hexahedron.
using Path = std::vector<int>;

template <class M>
typename M::Dart_handle follow(M& m, typename M::Dart_handle d, const Path& p) {
  for (int i : p) d = m.alpha(d, i);
  return d;
}

// Corner c (bits x, y, z) of the unit cube; make_hexahedron takes the bottom face
// counterclockwise, then the top corners above p3, p0, p1, p2.
static const int corner_of_arg[8] = {0b000, 0b001, 0b011, 0b010, 0b110, 0b100, 0b101, 0b111};

static Lcc::Point corner_point(int c, double x, double y, double z) {
  return Lcc::Point(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1));
}

template <class L>
typename L::Dart_handle make_hex(L& lcc, double x, double y, double z) {
  std::array<typename L::Point, 8> p;
  for (int a = 0; a < 8; ++a) {
    Lcc::Point q = corner_point(corner_of_arg[a], x, y, z);
    p[a] = typename L::Point(q.x(), q.y(), q.z());
  }
  return lcc.make_hexahedron(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
}

// For each axis, the paths to the dart of the hexahedron's upper face (coordinate 1 on that
// axis) and of its lower face (coordinate 0) that meet when a neighbour along the axis is
// 3-sewn: same vertex, same edge, matching faces.
struct SewPaths {
  Path upper[3], lower[3];
};

static SewPaths find_sew_paths() {
  Lcc proto;
  Lcc::Dart_handle d0 = make_hex(proto, 0, 0, 0);
  // shortest alpha path from d0 to every dart of the volume
  std::map<Lcc::Dart_handle, Path> path;
  std::queue<Lcc::Dart_handle> todo;
  path[d0] = {};
  todo.push(d0);
  while (!todo.empty()) {
    Lcc::Dart_handle d = todo.front();
    todo.pop();
    for (int i = 0; i <= 2; ++i) {
      Lcc::Dart_handle e = proto.alpha(d, i);
      if (!path.count(e)) {
        path[e] = path[d];
        path[e].push_back(i);
        todo.push(e);
      }
    }
  }
  auto find = [&](int axis, double side) {
    // the dart on the corner with only `axis` possibly set, on the edge along the next axis,
    // in the face at coordinate `side` on `axis`
    int next = (axis + 1) % 3, third = (axis + 2) % 3;
    for (auto& [d, p] : path) {
      Lcc::Point a = proto.point(d), b = proto.point(proto.alpha(d, 0));
      Lcc::Point c = proto.point(proto.alpha(d, 0, 1, 0));
      if (a[axis] == side && a[next] == 0 && a[third] == 0 && b[axis] == side && b[next] == 1 &&
          b[third] == 0 && c[axis] == side)
        return p;
    }
    std::fprintf(stderr, "no dart for axis %d side %g\n", axis, side);
    std::exit(1);
  };
  SewPaths s;
  for (int axis = 0; axis < 3; ++axis) {
    s.upper[axis] = find(axis, 1);
    s.lower[axis] = find(axis, 0);
  }
  return s;
}

template <class M>
typename M::Dart_handle make_cell(M& m, double x, double y, double z, int label);

template <>
Plain::Dart_handle make_cell(Plain& m, double, double, double, int) {
  return m.make_combinatorial_hexahedron();
}
template <>
Lcc::Dart_handle make_cell(Lcc& m, double x, double y, double z, int) {
  return make_hex(m, x, y, z);
}
template <>
LccLabel::Dart_handle make_cell(LccLabel& m, double x, double y, double z, int label) {
  LccLabel::Dart_handle d = make_hex(m, x, y, z);
  m.set_attribute<3>(d, m.create_attribute<3>(label));
  return d;
}

template <class M>
std::size_t vertex_attributes(const M&) {
  return 0;
}
template <>
std::size_t vertex_attributes(const Lcc& m) {
  return m.number_of_attributes<0>();
}
template <>
std::size_t vertex_attributes(const LccLabel& m) {
  return m.number_of_attributes<0>();
}

// The smallest times seen over the runs, wall clock and CPU.
struct Best {
  double build = 1e9, sew = 1e9, total = 1e9, cpu_build = 1e9, cpu_sew = 1e9;
  void keep(double t0, double t1, double t2, double c0, double c1, double c2) {
    build = std::min(build, t1 - t0);
    sew = std::min(sew, t2 - t1);
    total = std::min(total, t2 - t0);
    cpu_build = std::min(cpu_build, c1 - c0);
    cpu_sew = std::min(cpu_sew, c2 - c1);
  }
};

template <class M>
void run(const char* name, int k, int reps, const SewPaths& s) {
  Best b;
  std::vector<unsigned> cells;
  std::size_t darts = 0, vattrs = 0;
  bool valid = false;
  for (int r = 0; r < reps; ++r) {
    M m;
    std::vector<typename M::Dart_handle> hex((std::size_t)k * k * k);
    double c0 = cpu_now(), t0 = now();
    for (int z = 0; z < k; ++z)
      for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) {
          int i = (z * k + y) * k + x;
          hex[i] = make_cell(m, x, y, z, i);
        }
    double t1 = now(), c1 = cpu_now();
    const int step[3] = {1, k, k * k};
    for (int z = 0; z < k; ++z)
      for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) {
          int i = (z * k + y) * k + x, c[3] = {x, y, z};
          for (int axis = 0; axis < 3; ++axis)
            if (c[axis] + 1 < k)
              m.template sew<3>(follow(m, hex[i], s.upper[axis]),
                                follow(m, hex[i + step[axis]], s.lower[axis]));
        }
    double t2 = now(), c2 = cpu_now();
    b.keep(t0, t1, t2, c0, c1, c2);
    if (r == 0) {
      cells = m.count_all_cells();
      darts = m.number_of_darts();
      vattrs = vertex_attributes(m);
      valid = m.is_valid();
    }
  }
  std::printf("{\"engine\":\"CGAL %s\",\"k\":%d,\"darts\":%zu,\"cells\":[%u,%u,%u,%u],"
              "\"components\":%u,\"vertex_attributes\":%zu,\"valid\":%s,"
              "\"build_s\":%.4f,\"sew_s\":%.4f,\"build_and_sew_s\":%.4f,"
              "\"cpu_build_s\":%.4f,\"cpu_sew_s\":%.4f,\"peak_rss_kb\":%ld}\n",
              name, k, darts, cells[0], cells[1], cells[2], cells[3], cells[4], vattrs,
              valid ? "true" : "false", b.build, b.sew, b.total, b.cpu_build, b.cpu_sew, peak_rss_kb());
  std::fflush(stdout);
}

// The unsewn grid (every hexahedron with its points, as in `run<Lcc>`), then
// `sew3_same_facets`, which finds the faces to sew by their points: "build" is making the
// hexahedra, "sew" the call.
void run_same_facets(int k, int reps) {
  Best b;
  std::vector<unsigned> cells;
  std::size_t darts = 0, vattrs = 0;
  unsigned sewn = 0;
  bool valid = false;
  for (int r = 0; r < reps; ++r) {
    Lcc m;
    double c0 = cpu_now(), t0 = now();
    for (int z = 0; z < k; ++z)
      for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) make_hex(m, x, y, z);
    double t1 = now(), c1 = cpu_now();
    unsigned n = m.sew3_same_facets();
    double t2 = now(), c2 = cpu_now();
    b.keep(t0, t1, t2, c0, c1, c2);
    if (r == 0) {
      cells = m.count_all_cells();
      darts = m.number_of_darts();
      vattrs = m.number_of_attributes<0>();
      valid = m.is_valid();
      sewn = n;
    }
  }
  std::printf("{\"engine\":\"CGAL Linear_cell_complex_for_generalized_map<3> (points, sew3_same_facets)\","
              "\"k\":%d,\"darts\":%zu,\"cells\":[%u,%u,%u,%u],\"components\":%u,"
              "\"vertex_attributes\":%zu,\"valid\":%s,\"faces_sewn\":%u,"
              "\"build_s\":%.4f,\"sew_s\":%.4f,\"build_and_sew_s\":%.4f,"
              "\"cpu_build_s\":%.4f,\"cpu_sew_s\":%.4f,\"peak_rss_kb\":%ld}\n",
              k, darts, cells[0], cells[1], cells[2], cells[3], cells[4], vattrs,
              valid ? "true" : "false", sewn, b.build, b.sew, b.total, b.cpu_build, b.cpu_sew, peak_rss_kb());
  std::fflush(stdout);
}

int main(int argc, char** argv) {
  int k = argc > 1 ? std::atoi(argv[1]) : 40;
  int reps = argc > 2 ? std::atoi(argv[2]) : 3;
  std::string only = argc > 3 ? argv[3] : "";
  if (k < 1 || reps < 1 || !(only.empty() || only == "plain" || only == "lcc" || only == "lcc_label" ||
                              only == "same_facets")) {
    std::fprintf(stderr, "usage: cgal_lcc_grid [K>=1] [reps>=1] [plain|lcc|lcc_label|same_facets]\n");
    return 2;
  }
  SewPaths s = find_sew_paths();
  if (only.empty() || only == "plain") run<Plain>("Generalized_map<3> (no attributes)", k, reps, s);
  if (only.empty() || only == "lcc")
    run<Lcc>("Linear_cell_complex_for_generalized_map<3> (points)", k, reps, s);
  if (only.empty() || only == "lcc_label")
    run<LccLabel>("Linear_cell_complex_for_generalized_map<3> (points, int label per volume)", k, reps,
                  s);
  if (only.empty() || only == "same_facets") run_same_facets(k, reps);
  return 0;
}
