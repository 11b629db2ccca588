// Records CGAL 5.5.1's answers on the inputs of Surface_mesh_topology's cycle examples
// (shortest_noncontractible_cycle, edgewidth_surface_mesh, facewidth), for gmap's tests
// (tests/curves_cgal.rs). Build and run: see tests/data/cgal/README.md.
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>
#include <CGAL/Random.h>
#include <fstream>
#include <iostream>
#include <cmath>

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;
using Path = CGAL::Surface_mesh_topology::Path_on_surface<LCC>;
using CST = CGAL::Surface_mesh_topology::Curves_on_surface_topology<LCC>;

static double length(const LCC& lcc, const Path& p) {
  double r = 0;
  for (std::size_t i = 0; i < p.length(); ++i)
    r += std::sqrt(CGAL::squared_distance(lcc.point(p[i]), lcc.point(lcc.other_extremity(p[i]))));
  return r;
}

int main(int argc, char* argv[]) {
  if (argc < 2) { std::cerr << "usage: cycles FILE.off\n"; return 1; }
  LCC lcc;
  std::ifstream in(argv[1]);
  if (!CGAL::load_off(lcc, in)) { std::cerr << "cannot read " << argv[1] << "\n"; return 1; }
  std::cout.precision(17);
  std::cout << "file " << argv[1] << "\n";
  std::cout << "darts " << lcc.number_of_darts() << " vertices " << lcc.one_dart_per_cell<0>().size()
            << " edges " << lcc.one_dart_per_cell<1>().size() << " faces " << lcc.one_dart_per_cell<2>().size() << "\n";
  CST cst(lcc);
  CGAL::Surface_mesh_topology::Euclidean_length_weight_functor<LCC> wf(lcc);
  Path ew = cst.compute_edge_width();
  std::cout << "edgewidth " << ew.length() << "\n";
  Path sw = cst.compute_shortest_non_contractible_cycle(wf);
  std::cout << "shortest_euclidean " << sw.length() << " " << length(lcc, sw) << "\n";
  std::vector<LCC::Dart_const_handle> fw = cst.compute_face_width();
  std::cout << "facewidth_darts " << fw.size() << "\n";
  // the example's root: a dart drawn by the default random generator
  LCC::Dart_const_handle root = lcc.dart_handle(
      CGAL::get_default_random().get_int(0, static_cast<int>(lcc.number_of_darts())));
  Path c1 = cst.compute_shortest_non_contractible_cycle_with_base_point(root);
  Path c2 = cst.compute_shortest_non_contractible_cycle_with_base_point(root, wf);
  std::cout << "example_root " << lcc.point(root) << " unit " << c1.length() << " euclidean "
            << c2.length() << " " << length(lcc, c2) << "\n";
  // through every vertex: its point, the fewest edges, the shortest Euclidean length
  for (auto it = lcc.one_dart_per_cell<0>().begin(); it != lcc.one_dart_per_cell<0>().end(); ++it) {
    Path u = cst.compute_shortest_non_contractible_cycle_with_base_point(it);
    Path e = cst.compute_shortest_non_contractible_cycle_with_base_point(it, wf);
    std::cout << "through " << lcc.point(it) << " unit " << u.length() << " euclidean " << length(lcc, e) << "\n";
  }
  return 0;
}
