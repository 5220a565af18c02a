# Every dependency comes from a Debian 12 package through find_package; nothing is fetched.
# The order matters (BUILD_NOTES.md): MPI with C before VTK, Eigen's own config before VTK's
# FindEigen3 module shadows it.

find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Threads REQUIRED)
find_package(X11 REQUIRED)  # the view asks the display before VTK renders (x_display.h)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(SQLite3 REQUIRED)
# libzip's CMake config in bookworm references the zipcmp/zipmerge/ziptool programs of other
# packages; pkg-config needs none of them.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)
if(NOT TARGET libzip::zip)
  add_library(libzip::zip ALIAS PkgConfig::LIBZIP)
endif()
find_package(CGAL REQUIRED COMPONENTS ImageIO)
find_package(assimp REQUIRED)
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets Test)
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
  IOXML IOLegacy IOGeometry IOImage
  FiltersCore FiltersGeneral FiltersGeometry
  ImagingCore ImagingGeneral ImagingMorphological ImagingSources IOMINC
  GUISupportQt RenderingCore RenderingOpenGL2 RenderingVolumeOpenGL2 InteractionStyle InteractionWidgets
  ChartsCore ViewsContext2D RenderingContextOpenGL2 IOOggTheora RenderingFreeType RenderingContext2D)

# DICOM through GDCM's VTK reader (BUILD_NOTES.md). GDCMConfig.cmake does not load the
# GDCM::vtkgdcm target itself; its file sits beside the config and needs VTK found first.
find_package(GDCM REQUIRED)
if(NOT TARGET GDCM::vtkgdcm)
  include(${GDCM_DIR}/GDCM-targets.cmake)
endif()

# CGAL Mesh_3's parallel mode (CGAL::Parallel_tag) runs on TBB.
find_package(TBB REQUIRED)
include(CGAL_TBB_support)

# gmsh ships no CMake config (BUILD_NOTES.md).
find_library(GMSH_LIBRARY gmsh REQUIRED)
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
if(NOT TARGET Gmsh::gmsh)
  add_library(Gmsh::gmsh UNKNOWN IMPORTED)
  set_target_properties(Gmsh::gmsh PROPERTIES
    IMPORTED_LOCATION ${GMSH_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${GMSH_INCLUDE_DIR})
endif()

if(VISCERA_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(VISCERA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# SDL2 reads gamepads in the simulator window (dev.sh installs libsdl2-dev). Optional: a build
# without it lacks only the gamepad input (viscera-sim says so when asked for one).
find_package(SDL2 CONFIG QUIET)
if(TARGET SDL2::SDL2)
  message(STATUS "SDL2 ${SDL2_VERSION}: gamepad input enabled")
else()
  message(STATUS "SDL2 not found: viscera-sim builds without gamepad input")
endif()
