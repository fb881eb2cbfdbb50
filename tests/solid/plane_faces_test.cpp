// SPDX-License-Identifier: GPL-3.0-or-later
// has_no_faces (detail/plane_faces.h): the shortcut that skips a plane's 2D boolean must
// never skip a plane with a face on it; and what PlaneBoolean leaves out. Rectangles on the
// plane z = 0: a face with solid below it, and solid polygons above.
#include "solid/detail/general_path/plane_faces.h"
#include "solid/detail/general_path/plane_contributions.h"

#include <gtest/gtest.h>

#include <vector>

namespace roomcad::detail {
namespace {

struct Plane {
  PlaneSet set;
  PlaneId z = set.add_axis(2, 0.0);

  // The rectangle [x0, x1] x [y0, y1] of z = 0, counter-clockwise seen from above.
  PlanePolygon rectangle(double x0, double y0, double x1, double y1) {
    const PlaneRef left{set.add_axis(0, x0), -1}, bottom{set.add_axis(1, y0), -1};
    const PlaneRef right{set.add_axis(0, x1), 1}, top{set.add_axis(1, y1), 1};
    PlanePolygon p{{z, 1}, {left, bottom, right, top}, {}};
    for (const auto& [a, b] : {std::pair{left, bottom}, std::pair{bottom, right},
                               std::pair{right, top}, std::pair{top, left}})
      p.vertices.push_back(make_point(set, z, a.id, b.id));
    return p;
  }
  // A solid's face on the plane with the solid below it (primitive 0).
  Contribution face_below(double x0, double y0, double x1, double y1) {
    return {rectangle(x0, y0, x1, y1), 0, true, false, true};
  }
  // A solid above the plane there, with a face on it (primitive k).
  Contribution solid_above(double x0, double y0, double x1, double y1, std::size_t k) {
    return {rectangle(x0, y0, x1, y1), k, true, true, false};
  }
};

TEST(PlaneFaces, AFaceCoveredByOneSolidOnItsOtherSide) {
  Plane p;
  // The covering face has solid above and nothing below beyond the face: a face remains there.
  EXPECT_FALSE(has_no_faces(p.set, {p.face_below(0, 0, 2, 2), p.solid_above(-1, -1, 3, 3, 1)}));
  EXPECT_TRUE(has_no_faces(p.set, {p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 2, 2, 1)}));
}

TEST(PlaneFaces, AFaceCoveredByTheUnionOfSeveral) {
  Plane p;
  // Two storeys' walls meeting on the plane: the lower one's top under two upper ones.
  const std::vector<Contribution> whole{p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 1, 2, 1),
                                        p.solid_above(1, 0, 2, 2, 2), p.face_below(0, 0, 1, 2),
                                        p.face_below(1, 0, 2, 2)};
  EXPECT_TRUE(has_no_faces(p.set, whole));
  // A strip of the lower top left uncovered (1.5 .. 1.6): a face there.
  const std::vector<Contribution> gap{p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 1.5, 2, 1),
                                      p.solid_above(1.6, 0, 2, 2, 2)};
  EXPECT_FALSE(has_no_faces(p.set, gap));
  // A corner of the lower top (2, 2) beyond both upper ones (the second stops at y = 1.9).
  const std::vector<Contribution> corner{p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 1, 2, 1),
                                         p.solid_above(1, 0, 2, 1.9, 2)};
  EXPECT_FALSE(has_no_faces(p.set, corner));
  // Covered, but the upper faces reach beyond the lower one (y up to 3): faces there.
  const std::vector<Contribution> beyond{p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 1, 3, 1),
                                         p.solid_above(1, 0, 2, 3, 2)};
  EXPECT_FALSE(has_no_faces(p.set, beyond));
}

TEST(PlaneFaces, FacesHeldByDifferentCovers) {
  Plane p;
  // One cover holds the first two faces (the second is asked of it first), another the third.
  const std::vector<Contribution> held{p.face_below(0, 0, 1, 1), p.face_below(1, 0, 2, 1),
                                       p.face_below(5, 0, 6, 1), p.solid_above(5, 0, 6, 1, 1),
                                       p.solid_above(0, 0, 2, 1, 2)};
  EXPECT_TRUE(has_no_faces(p.set, held));
  // The third face reaches beyond its cover (x up to 6.5): a face there.
  std::vector<Contribution> beyond = held;
  beyond[2] = p.face_below(5, 0, 6.5, 1);
  EXPECT_FALSE(has_no_faces(p.set, beyond));
}

TEST(PlaneFaces, AFaceWhoseCornersAreCoveredButNotItsMiddle) {
  Plane p;
  // Two upper walls over the two ends of a lower wall's top: every corner of the top is held,
  // its middle (1, 0.5) is not.
  EXPECT_FALSE(has_no_faces(p.set, {p.face_below(0, 0, 2, 1), p.solid_above(0, 0, 0.9, 1, 1),
                                    p.solid_above(1.1, 0, 2, 1, 2)}));
}

TEST(PlaneFaces, AHoleWithAFaceOnThePlaneKeepsIt) {
  Plane p;
  Contribution hole = p.solid_above(0.5, 0.5, 1, 1, 3);
  hole.solid = false;
  EXPECT_FALSE(has_no_faces(p.set, {p.face_below(0, 0, 2, 2), p.solid_above(0, 0, 2, 2, 1), hole}));
}

// A polygon inside a solid section has no say in the faces (solid lies above and below there
// whatever it says): it leaves no vertex on them. Here its corners touch the edge that a face
// beside the section shares with it.
TEST(PlaneFaces, APolygonInsideASolidSectionLeavesNoVertexOnTheFaces) {
  Plane p;
  const Contribution section{p.rectangle(0, 0, 2, 2), 1, true, true, true};
  const Contribution inside = p.face_below(1, 0.5, 2, 1.5);
  Contribution beside = p.face_below(2, 0, 4, 2);
  beside.primitive = 2;
  const PlaneFaces faces = PlaneBoolean(p.set, {p.z, 1}, {section, inside, beside}).faces();
  ASSERT_EQ(faces.faces.size(), 1u);
  EXPECT_TRUE(faces.holes.empty());
  EXPECT_EQ(faces.faces[0].owner, 2u);
  EXPECT_EQ(faces.faces[0].vertices.size(), 4u);  // not 6: (2, 0.5) and (2, 1.5) are no corners
}

}  // namespace
}  // namespace roomcad::detail
