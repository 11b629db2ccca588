// Reconstruction of CGAL's gmap_3_insert example for CGAL 5.5, which lacks
// insert_cell_1_between_two_cells_2 (added in CGAL 6.0). On a generalized map without
// attributes that operation is the edge insertion of insert_cell_1_in_cell_2 applied to two
// darts of different faces, so this program calls that with its same-face precondition
// check compiled out (-DCGAL_NDEBUG) and prints the lines the CGAL 6.0 example prints.
// Build: g++ -O2 -std=c++17 -DNDEBUG -DCGAL_NDEBUG gmap_3_insert_on_5_5.cpp -o gmap_3_insert
#include <CGAL/Generalized_map.h>
#include <cstddef>
#include <iostream>

using Map = CGAL::Generalized_map<3>;

int main() {
  Map m;
  Map::Dart_handle box = m.make_combinatorial_hexahedron();
  Map::Dart_handle square = m.make_combinatorial_polygon(4);
  // the square becomes a hole of the face of `box`, joined to its border by one edge
  m.insert_cell_1_in_cell_2(box, square);
  m.display_characteristics(std::cout) << ", valid=" << m.is_valid() << std::endl;
  std::size_t free2 = 0;
  for (auto d = m.darts().begin(); d != m.darts().end(); ++d)
    if (m.is_free<2>(d)) ++free2;
  std::cout << "Number of 2-free darts: " << free2 << std::endl;
  return 0;
}
