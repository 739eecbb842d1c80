#pragma once
// What this binary was built from: dtlab's version, the git commit of the source tree
// at build time ("unknown" outside a git checkout; "-dirty" when tracked files had
// changes), the compiler, and the versions of the libraries and tools it uses.
// Implemented by a file generated at build time (cmake/build_info.cmake).
namespace dtlab {

const char* build_version();
const char* build_commit();
const char* build_compiler();
const char* build_type();
const char* build_cgal_version();    // CGAL headers found at configure time
const char* build_tetgen_version();  // the tetgen binary's Debian package, "not found" without one
const char* build_gmp_version();     // gmp.h compiled against
const char* runtime_gmp_version();   // libgmp loaded at run time

}  // namespace dtlab
