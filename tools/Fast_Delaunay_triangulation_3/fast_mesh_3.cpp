// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// fast_mesh_3 INPUT... -o OUTPUT [--size H] [--size-field FILE] [--threads K]
//             [--optimize 0|1] [--quality-threshold G] [--dihedral-target D]
//             [--remesh-surface L] [--quiet]
//
// Meshes the volumes bounded by the closed surfaces of the input files (OFF,
// STL, OBJ, PLY) with the Delaunay-refinement mesher of the paper's §4,
// improves the tetrahedra under the gamma threshold or the dihedral target
// (unless --optimize 0); with --remesh-surface, the surfaces are first
// remeshed to edge length L (Surface_remeshing.h; shorter, up to three
// times by 10%, while the mesh keeps flat tetrahedra on walls narrower
// than L), so the boundary is no longer the input's triangles
// and writes OUTPUT as Medit (.mesh), VTK (.vtu) or Gmsh 4.1 (.msh), by
// extension.
// Prints the phases' times, a progress line per refinement pass (one line
// redrawn in place when stdout is a terminal) and the quality report,
// unless --quiet.

#include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include "Progress_bar.h"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

// Each remeshing attempt's shortening as the help and the report write it,
// from the library's factor, so that the words follow the code.
std::string shortening_percent()
{
  return std::to_string(std::lround(100 * (1 - CGAL::Fast_mesher_3::remeshing_detail::shortening_factor))) + "%";
}

int usage(const char* program)
{
  std::cerr << "usage: " << program
            << " INPUT... -o OUTPUT [--size H] [--size-field FILE] [--threads K] [--optimize 0|1]\n"
            << "       [--quality-threshold G] [--dihedral-target D] [--remesh-surface L] [--quiet]\n"
            << "  INPUT   closed triangulated surfaces (.off .stl .obj .ply); nested surfaces give several subdomains\n"
            << "  OUTPUT  .mesh (Medit), .vtu (VTK) or .msh (Gmsh 4.1)\n"
            << "  --size H     maximum mesh size (default: the surface's edge lengths, interpolated)\n"
            << "  --size-field FILE  sizes from a text file, one entry a line ('#' comments):\n"
            << "               'subdomain S H' caps h in subdomain S; 'X Y Z H' is a background point whose\n"
            << "               size H caps h where it is the nearest one\n"
            << "  --threads K  Moore partitions (threads) of the empty mesh and of every refinement batch;\n"
            << "               the same input and K give the same mesh\n"
            << "  --optimize 0|1  improve the tetrahedra under the threshold after refinement (default 1)\n"
            << "  --quality-threshold G  gamma = 3 r_in / r_circ to reach, in (0, 1) (default 0.3)\n"
            << "  --dihedral-target D    smallest dihedral angle to reach, degrees in [0, 70] (default 15;\n"
            << "                         0: gamma alone)\n"
            << "  --remesh-surface L     remesh the surfaces to edge length L first (edges where the normals\n"
            << "                         differ by over 60 degrees kept as polylines): the boundary is then\n"
            << "                         not the input's triangles, and h follows L where no smaller size is given;\n"
            << "                         remeshed up to " << CGAL::Fast_mesher_3::Surface_remeshing_options().shortenings
            << " times " << shortening_percent() << " shorter while walls narrower than the\n"
            << "                         triangles leave bad tetrahedra with four vertices on the surface\n"
            << "                         (with --optimize 1, which counts them)\n"
            << "  --quiet      print nothing but errors\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> inputs;
  std::string output, size_field;
  CGAL::Fast_mesher_3::Mesher_options options;
  bool quiet = false;
  CGAL::Fast_mesher_3::Surface_remeshing_options remeshing; // target_edge_length 0: no remeshing
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::cerr << "fast_mesh_3: " << arg << " needs a value\n";
        std::exit(usage(argv[0]));
      }
      return argv[++i];
    };
    try {
      if(arg == "-o" || arg == "--output") output = value();
      else if(arg == "--size") options.maximum_size = std::stod(value());
      else if(arg == "--size-field") size_field = value();
      else if(arg == "--threads") options.threads = std::stoi(value());
      else if(arg == "--optimize") {
        const std::string v = value();
        if(v != "0" && v != "1") throw std::invalid_argument(v);
        options.optimize = v == "1";
      } else if(arg == "--quality-threshold") options.quality_threshold = std::stod(value());
      else if(arg == "--dihedral-target") options.min_dihedral_target = std::stod(value());
      else if(arg == "--remesh-surface") {
        remeshing.target_edge_length = std::stod(value());
        if(!(remeshing.target_edge_length > 0) || std::isinf(remeshing.target_edge_length))
          throw std::invalid_argument("length");
      } else if(arg == "--quiet") quiet = true;
      else if(arg == "-h" || arg == "--help") return usage(argv[0]);
      else if(!arg.empty() && arg[0] == '-') {
        std::cerr << "fast_mesh_3: unknown option " << arg << "\n";
        return usage(argv[0]);
      } else inputs.push_back(arg);
    } catch(const std::exception&) {
      std::cerr << "fast_mesh_3: bad value for " << arg << "\n";
      return usage(argv[0]);
    }
  }
  if(inputs.empty() || output.empty()) return usage(argv[0]);
  if(!(options.maximum_size > 0) || options.threads < 1 ||
     !(options.quality_threshold > 0 && options.quality_threshold < 1) ||
     !(options.min_dihedral_target >= 0 && options.min_dihedral_target <= 70)) {
    std::cerr << "fast_mesh_3: --size must be positive, --threads at least 1, --quality-threshold in (0, 1) and "
                 "--dihedral-target in [0, 70]\n";
    return 2;
  }
  if(!size_field.empty()) {
    try {
      CGAL::Fast_mesher_3::read_size_field(size_field, options);
    } catch(const std::exception& e) {
      std::cerr << "fast_mesh_3: " << e.what() << "\n";
      return 1;
    }
  }
  fdt3_tools::Progress_bar bar(stdout, !quiet);
  if(bar.enabled())
    options.progress = [&bar](int pass, std::size_t inserted, std::size_t tetrahedra) {
      bar.update("refine", "pass " + std::to_string(pass + 1) + ": " + std::to_string(inserted) +
                               " points inserted, " + std::to_string(tetrahedra) + " tetrahedra");
    };
  else if(!quiet)
    options.progress = [](int pass, std::size_t inserted, std::size_t tetrahedra) {
      std::cout << "  refinement pass " << pass + 1 << ": " << inserted << " points inserted, " << tetrahedra
                << " tetrahedra\n" << std::flush;
    };

  try {
    CGAL::Fast_mesher_3::Mesher_statistics stats;
    CGAL::Fast_mesher_3::Tetrahedral_mesh mesh;
    if(remeshing.target_edge_length > 0) {
      mesh = CGAL::Fast_mesher_3::mesh_remeshed_surface_files(inputs, remeshing, options, &stats);
    } else {
      mesh = CGAL::Fast_mesher_3::mesh_surface_files(inputs, options, &stats);
    }
    CGAL::Fast_mesher_3::write_mesh(output, mesh);
    bar.finish();
    if(!quiet) {
      if(remeshing.target_edge_length > 0) {
        std::cout << "surface remeshing       " << stats.remeshing_seconds << " s (remeshed to "
                  << stats.remeshed_triangles << " triangles of edge length about " << stats.remeshed_edge_length;
        if(stats.remeshing_attempts > 1)
          std::cout << "; " << stats.remeshing_attempts
                    << " attempts, each " << shortening_percent() << " shorter while bad tetrahedra with four vertices on the surface remained, "
                    << stats.discarded_meshing_seconds << " s meshing those not kept";
        std::cout << ")\n";
      }
      std::cout << "input (read and check)  " << stats.input_seconds << " s\n"
                << "empty mesh              " << stats.empty_mesh_seconds << " s\n"
                << "boundary recovery       " << stats.recovery_seconds << " s ("
                << stats.missing_triangles << " surface triangles missing from the empty mesh"
                << (stats.missing_triangles == 0 ? std::string()
                    : stats.whole_surface_to_tetgen
                        ? ", recovered by TetGen on the whole surface"
                        : ", recovered locally on " + std::to_string(stats.recovery_region_tetrahedra) +
                              " tetrahedra, " + std::to_string(stats.flipped_components) + " parts by flips and " +
                              std::to_string(stats.tetgen_components) + " by TetGen")
                << (stats.used_tetgen ? " with " + std::to_string(stats.steiner_points) + " interior Steiner points"
                                      : std::string())
                << ")\n"
                << "colouring and sizes     " << stats.colouring_seconds << " s"
                << (stats.triangles_over_size == 0
                        ? std::string("\n")
                        : " (" + std::to_string(stats.triangles_over_size) +
                              " surface triangles over the size next to them: the surface is never split, so the "
                              "tetrahedra along them stay large or flat; remesh the surface to the size first: "
                              "--remesh-surface L)\n")
                << "refinement              " << stats.refinement_seconds << " s (" << stats.refinement_passes
                << " passes, " << stats.refinement_points << " points inserted, " << stats.filtered_points
                << " filtered, " << stats.aborted_points << " aborted; "
                << stats.points_settled_in_partitions << " points settled by " << stats.partitioned_attempts
                << " partitioned attempts)\n"
                << "  sample, filter, insert " << stats.sample_seconds << " s, " << stats.filter_seconds << " s, "
                << stats.insert_seconds << " s\n"
                << "improvement             " << stats.improvement_seconds << " s";
      if(options.optimize) {
        const auto& im = stats.improvement;
        std::cout << " (" << im.passes << " passes: " << im.edge_removals << " edge removals, " << im.face_removals
                  << " face removals, " << im.relocations << " relocations, " << im.steiner_points
                  << " Steiner points, " << im.deferred
                  << " deferred between partitions)\n"
                  << "  tetrahedra under gamma " << options.quality_threshold << ": " << im.bad_before << " before, "
                  << im.bad_after << " after (" << im.bad_after_on_surface
                  << " with all four vertices on the surface; " << im.bad_after_forced_by_surface
                  << " forced: on a surface triangle under which no tetrahedron reaches "
                  << options.quality_threshold << "); min gamma " << im.min_gamma_before << " -> "
                  << im.min_gamma_after << "\n"
                  << "  smallest dihedral angle " << im.min_dihedral_before << " -> " << im.min_dihedral_after
                  << " degrees; tetrahedra under 10 degrees " << im.below_10_degrees_before << " -> "
                  << im.below_10_degrees_after << "\n";
      } else {
        std::cout << " (--optimize 0)\n";
      }
      std::cout << "total (without input)   " << stats.total_seconds << " s, "
                << (stats.total_seconds > 0 ? mesh.tetrahedra.size() / stats.total_seconds : 0)
                << " tetrahedra per second\n";
      CGAL::Fast_mesher_3::print_quality_report(std::cout,
                                                CGAL::Fast_mesher_3::quality_report(mesh, options.threads));
      std::cout << "wrote " << output << "\n";
    }
  } catch(const std::exception& e) {
    bar.finish();
    std::cerr << "fast_mesh_3: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
