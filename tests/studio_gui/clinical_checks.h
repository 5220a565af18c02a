#pragma once
/// Measurements the issue-23 studio tests share: image differences, the wall side of a point on
/// the uterus, and whether the scene tree, the 3D view and the document's view state agree.

#include <QImage>
#include <QString>

#include "core/mesh/surface_mesh.h"
#include "studio/ui/main_window.h"
#include "templates/geometry/surface_queries.h"

namespace viscera::studio_tests {

/// Share of pixels that differ between two images of one size by more than 24 grey levels
/// (1 for images of different sizes).
double changed_share(const QImage& a, const QImage& b);

/// Whether the triangle of `wall` nearest to `p` lies on the cavity wall: all three vertices
/// marked 1 by the "cavity" vertex attribute.
bool on_cavity_side(const core::SurfaceMesh& wall, const templates::SurfaceQueries& queries,
                    const core::Vec3& p);

/// The first disagreement between the tree's boxes, the 3D view and the document's view state
/// (visibility and opacity of every object, visibility of every vessel tree), or empty.
QString disagreement(studio::MainWindow& window);

}  // namespace viscera::studio_tests
