// Reads a grasp file of any format graspecmf knows and writes it in another (by extension).
#include <iostream>

#include "graspecmf/core/error.hpp"
#include "graspecmf/formats/grasp_files.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: convert_grasps IN OUT\n";
    return 2;
  }
  try {
    const graspecmf::formats::GraspSet grasps = graspecmf::formats::read_grasps(argv[1]);
    graspecmf::formats::write_grasps(grasps, argv[2]);
    std::cout << grasps.size() << " grasps written to " << argv[2] << "\n";
  } catch (const graspecmf::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
