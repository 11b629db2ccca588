// Records CGAL 5.5.1's answers to the homotopy questions of Surface_mesh_topology's
// examples path_homotopy_double_torus, open_path_homotopy (on double-torus-example.off, with
// the deterministic paths of double-torus-paths.txt, made by make_paths.py, in place of the
// examples' random ones) and path_homotopy_with_symbols (its own schema and paths), for
// gmap's tests (tests/curves_homotopy.rs). Build and run: see tests/data/cgal/README.md.
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>
#include <CGAL/Polygonal_schema.h>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;
using Path = CGAL::Surface_mesh_topology::Path_on_surface<LCC>;
using CST = CGAL::Surface_mesh_topology::Curves_on_surface_topology<LCC>;
using PS = CGAL::Surface_mesh_topology::Polygonal_schema_with_combinatorial_map<>;

int main(int argc, char* argv[]) {
  if (argc < 3) { std::cerr << "usage: homotopy FILE.off PATHS.txt\n"; return 1; }
  // path_homotopy_with_symbols, as the example writes it
  {
    PS ps;
    ps.add_facet("a b -a -b c d -c -d");
    CGAL::Surface_mesh_topology::Path_on_surface<PS> p1(ps); p1.push_back_by_label("a");
    CGAL::Surface_mesh_topology::Path_on_surface<PS> p2(ps); p2.push_back_by_label("b c a -c -b");
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<PS> cst(ps);
    std::cout << "symbols free " << cst.are_freely_homotopic(p1, p2) << "\n";
    std::cout << "symbols fixed " << cst.are_base_point_homotopic(p1, p2) << "\n";
  }
  LCC lcc;
  std::ifstream in(argv[1]);
  if (!CGAL::load_off(lcc, in)) { std::cerr << "cannot read " << argv[1] << "\n"; return 1; }
  // the .off's vertex indices, by their points (the file's points are distinct)
  std::vector<LCC::Point> points;
  {
    std::ifstream f(argv[1]);
    std::string off; std::size_t nv, nf, ne;
    f >> off >> nv >> nf >> ne;
    for (std::size_t i = 0; i < nv; ++i) { double x, y, z; f >> x >> y >> z; points.emplace_back(x, y, z); }
  }
  std::map<LCC::Point, std::size_t> index;
  for (std::size_t i = 0; i < points.size(); ++i) index[points[i]] = i;
  auto vertex = [&](LCC::Dart_const_handle d) { return index.at(lcc.point(d)); };
  CST cst(lcc);
  std::map<std::string, Path> paths;
  std::ifstream q(argv[2]);
  std::string line;
  while (std::getline(q, line)) {
    std::istringstream s(line);
    std::string what, a, b;
    s >> what >> a;
    if (what == "path") {
      std::vector<std::size_t> vs; std::size_t v;
      while (s >> v) vs.push_back(v);
      Path p(lcc);
      for (std::size_t k = 0; k + 1 < vs.size(); ++k) {
        // the dart leaving vertex vs[k] towards vs[k + 1]
        bool found = false;
        for (auto it = lcc.darts().begin(); it != lcc.darts().end() && !found; ++it) {
          if (vertex(it) == vs[k] && vertex(lcc.other_extremity(it)) == vs[k + 1]) { p.push_back(it); found = true; }
        }
        if (!found) { std::cerr << "no edge " << vs[k] << " " << vs[k + 1] << "\n"; return 1; }
      }
      paths.emplace(a, p);
    } else if (what == "contractible") {
      std::cout << line << " " << cst.is_contractible(paths.at(a)) << "\n";
    } else if (what == "free") {
      s >> b;
      std::cout << line << " " << cst.are_freely_homotopic(paths.at(a), paths.at(b)) << "\n";
    } else if (what == "fixed") {
      s >> b;
      std::cout << line << " " << cst.are_base_point_homotopic(paths.at(a), paths.at(b)) << "\n";
    }
  }
  return 0;
}
