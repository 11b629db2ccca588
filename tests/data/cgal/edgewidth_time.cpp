// Times CGAL 5.5.1's compute_edge_width() (and the shortest Euclidean non-contractible
// cycle) on an .off surface, for the comparison in docs/CURVES.md.
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Curves_on_surface_topology.h>
#include <chrono>
#include <fstream>
#include <iostream>

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;
using CST = CGAL::Surface_mesh_topology::Curves_on_surface_topology<LCC>;

int main(int argc, char* argv[]) {
  LCC lcc;
  std::ifstream in(argv[1]);
  if (argc < 2 || !CGAL::load_off(lcc, in)) { std::cerr << "usage: edgewidth_time FILE.off\n"; return 1; }
  auto t0 = std::chrono::steady_clock::now();
  CST cst(lcc);
  auto p = cst.compute_edge_width();
  auto t1 = std::chrono::steady_clock::now();
  CGAL::Surface_mesh_topology::Euclidean_length_weight_functor<LCC> wf(lcc);
  auto q = cst.compute_shortest_non_contractible_cycle(wf);
  auto t2 = std::chrono::steady_clock::now();
  std::cout << "edgewidth " << p.length() << " in " << std::chrono::duration<double>(t1 - t0).count()
            << " s; shortest euclidean " << q.length() << " edges in "
            << std::chrono::duration<double>(t2 - t1).count() << " s\n";
  return 0;
}
