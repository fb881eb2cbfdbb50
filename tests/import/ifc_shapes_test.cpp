// SPDX-License-Identifier: GPL-3.0-or-later
// The shapes BIM tools write, each in a small hand-written IFC file: walls over composite and
// indexed curves with arcs, an arc wall's trimmed-circle axis, clipping half-spaces (a sloped
// top, a gable), an upright profile, slab openings, curtain walls, a mapped item and the
// site's location and north.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "import/ifc_import.h"
#include "plan/plan_levels.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

/// A model in metres whose DATA section holds `entities` after a shared preamble: #1 the
/// origin, #2 its 3D placement, #3 a local placement there, #4 the z direction, #5 the x
/// direction.
std::string ifc_text(const std::string& entities) {
  return "ISO-10303-21;HEADER;FILE_SCHEMA(('IFC4'));ENDSEC;DATA;\n"
         "#1=IFCCARTESIANPOINT((0.,0.,0.));\n#2=IFCAXIS2PLACEMENT3D(#1,$,$);\n"
         "#3=IFCLOCALPLACEMENT($,#2);\n#4=IFCDIRECTION((0.,0.,1.));\n"
         "#5=IFCDIRECTION((1.,0.,0.));\n" +
         entities + "ENDSEC;END-ISO-10303-21;\n";
}

/// A straight wall 'w' 10 m along x, 0.2 m thick and 3 m high, its body `body` (an item id).
std::string straight_wall(const std::string& body) {
  return "#10=IFCCARTESIANPOINT((0.,0.));\n#11=IFCCARTESIANPOINT((10.,0.));\n"
         "#12=IFCPOLYLINE((#10,#11));\n#13=IFCSHAPEREPRESENTATION($,'Axis','Curve2D',(#12));\n"
         "#14=IFCCARTESIANPOINT((5.,0.));\n#15=IFCAXIS2PLACEMENT2D(#14,$);\n"
         "#16=IFCRECTANGLEPROFILEDEF(.AREA.,$,#15,10.,0.2);\n"
         "#17=IFCEXTRUDEDAREASOLID(#16,#2,#4,3.);\n"
         "#18=IFCSHAPEREPRESENTATION($,'Body','Clipping',(" +
         body +
         "));\n#19=IFCPRODUCTDEFINITIONSHAPE($,$,(#13,#18));\n"
         "#20=IFCWALL('0123456789abcdefghijkl',$,'w',$,$,#3,#19,$,$);\n";
}

const IfcEntityTally& type_tally(const IfcImport& r, const char* type) {
  static const IfcEntityTally kNone{};
  const auto it = r.tally.find(type);
  return it == r.tally.end() ? kNone : it->second;
}

void expect_format_valid(const Plan& plan) {
  for (const Diagnostic& d : validate(plan).items) {
    EXPECT_NE(d.code, Code::invalid_value) << d.message;
    EXPECT_NE(d.code, Code::out_of_bounds) << d.message;
  }
}

TEST(IfcShapes, ATrimmedCircleAxisMakesAnArcWallOverACompositeProfile) {
  // A quarter circle of radius 5 from (5, 0) to (0, 5); the footprint between radii 4.9 and
  // 5.1, its inner arc walked backwards (SameSense false).
  const std::string text = ifc_text(
      "#10=IFCCARTESIANPOINT((0.,0.));\n#11=IFCAXIS2PLACEMENT2D(#10,$);\n"
      "#12=IFCCIRCLE(#11,5.);\n#13=IFCCARTESIANPOINT((5.,0.));\n#14=IFCCARTESIANPOINT((0.,5.));\n"
      "#15=IFCTRIMMEDCURVE(#12,(#13),(#14),.T.,.CARTESIAN.);\n"
      "#16=IFCSHAPEREPRESENTATION($,'Axis','Curve2D',(#15));\n"
      "#20=IFCCIRCLE(#11,5.1);\n#21=IFCCIRCLE(#11,4.9);\n"
      "#22=IFCCARTESIANPOINT((5.1,0.));\n#23=IFCCARTESIANPOINT((0.,5.1));\n"
      "#24=IFCCARTESIANPOINT((0.,4.9));\n#25=IFCCARTESIANPOINT((4.9,0.));\n"
      "#26=IFCTRIMMEDCURVE(#20,(#22),(#23),.T.,.CARTESIAN.);\n#27=IFCPOLYLINE((#23,#24));\n"
      "#28=IFCTRIMMEDCURVE(#21,(IFCPARAMETERVALUE(0.)),(IFCPARAMETERVALUE(1.5707963267948966)),"
      ".T.,.PARAMETER.);\n#29=IFCPOLYLINE((#25,#22));\n"
      "#30=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.T.,#26);\n"
      "#31=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.T.,#27);\n"
      "#32=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.F.,#28);\n"
      "#33=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.T.,#29);\n"
      "#34=IFCCOMPOSITECURVE((#30,#31,#32,#33),.F.);\n"
      "#35=IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,#34);\n"
      "#37=IFCEXTRUDEDAREASOLID(#35,#2,#4,3.);\n"
      "#38=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#37));\n"
      "#39=IFCPRODUCTDEFINITIONSHAPE($,$,(#16,#38));\n"
      "#40=IFCWALL('0123456789abcdefghijkl',$,'curved',$,$,#3,#39,$,$);\n");
  const Result<IfcImport> r = import_ifc_text(text, "arc.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().plan.walls.size(), 1u);
  const Wall& w = r.value().plan.walls[0];
  ASSERT_TRUE(w.arc_extent.has_value());
  EXPECT_NEAR(*w.arc_extent, 90.0, 1e-6);
  EXPECT_NEAR(w.from.x, 5.0, 1e-6);
  EXPECT_NEAR(w.from.y, 0.0, 1e-6);
  EXPECT_NEAR(w.to.x, 0.0, 1e-6);
  EXPECT_NEAR(w.to.y, 5.0, 1e-6);
  EXPECT_NEAR(w.thickness, 0.2, 1e-6);
  EXPECT_NEAR(w.height, 3.0, 1e-6);
  // Its arcs are chords: approximated by at most a millimetre, and said so.
  const IfcEntityTally& t = type_tally(r.value(), "IFCWALL");
  EXPECT_EQ(t.read, 1u);
  EXPECT_EQ(t.approximated, 1u);
  EXPECT_NEAR(t.distance, 0.001, 1e-12);
  EXPECT_EQ(t.unmeasured, 0u);
  expect_format_valid(r.value().plan);
}

TEST(IfcShapes, OneSlopedHalfSpaceIsASlopedTopExactly) {
  // The plane through (0, 0, 3) and (10, 0, 2): its normal (0.1, 0, 1) points into the
  // removed side (AgreementFlag false).
  const std::string text = ifc_text(straight_wall("#53") +
                                    "#50=IFCCARTESIANPOINT((0.,0.,3.));\n"
                                    "#51=IFCDIRECTION((0.1,0.,1.));\n"
                                    "#54=IFCAXIS2PLACEMENT3D(#50,#51,#5);\n#55=IFCPLANE(#54);\n"
                                    "#56=IFCHALFSPACESOLID(#55,.F.);\n"
                                    "#53=IFCBOOLEANCLIPPINGRESULT(.DIFFERENCE.,#17,#56);\n");
  const Result<IfcImport> r = import_ifc_text(text, "slope.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().plan.walls.size(), 1u);
  const Wall& w = r.value().plan.walls[0];
  EXPECT_NEAR(w.height, 3.0, 1e-6);
  ASSERT_TRUE(w.height_at_end.has_value());
  EXPECT_NEAR(*w.height_at_end, 2.0, 1e-6);
  EXPECT_EQ(type_tally(r.value(), "IFCWALL").approximated, 0u);
  expect_format_valid(r.value().plan);
}

TEST(IfcShapes, TwoHalfSpacesMeetingOverAWallAreAGableOfTwoWalls) {
  // Roof planes rising from 3 m at both ends to 5 m in the middle.
  const std::string text = ifc_text(straight_wall("#60") +
                                    "#50=IFCCARTESIANPOINT((0.,0.,3.));\n"
                                    "#51=IFCDIRECTION((-0.4,0.,1.));\n"
                                    "#52=IFCAXIS2PLACEMENT3D(#50,#51,$);\n#53=IFCPLANE(#52);\n"
                                    "#54=IFCHALFSPACESOLID(#53,.F.);\n"
                                    "#55=IFCCARTESIANPOINT((10.,0.,3.));\n"
                                    "#56=IFCDIRECTION((0.4,0.,1.));\n"
                                    "#57=IFCAXIS2PLACEMENT3D(#55,#56,$);\n#58=IFCPLANE(#57);\n"
                                    "#59=IFCHALFSPACESOLID(#58,.F.);\n"
                                    "#61=IFCBOOLEANCLIPPINGRESULT(.DIFFERENCE.,#62,#54);\n"
                                    "#60=IFCBOOLEANCLIPPINGRESULT(.DIFFERENCE.,#61,#59);\n"
                                    "#62=IFCEXTRUDEDAREASOLID(#16,#2,#4,6.);\n");
  const Result<IfcImport> r = import_ifc_text(text, "gable.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  ASSERT_EQ(plan.walls.size(), 2u);
  EXPECT_NEAR(plan.walls[0].to.x, 5.0, 1e-6);
  EXPECT_NEAR(plan.walls[0].height, 3.0, 1e-6);
  EXPECT_NEAR(plan.walls[0].height_at_end.value_or(0.0), 5.0, 1e-6);
  EXPECT_NEAR(plan.walls[1].height, 5.0, 1e-6);
  EXPECT_NEAR(plan.walls[1].height_at_end.value_or(0.0), 3.0, 1e-6);
  EXPECT_EQ(plan.walls[1].id, "w (2)");
  // Approximated only in being two walls: the distance is nought.
  const IfcEntityTally& t = type_tally(r.value(), "IFCWALL");
  EXPECT_EQ(t.read, 1u);
  EXPECT_EQ(t.approximated, 1u);
  EXPECT_EQ(t.distance, 0.0);
  EXPECT_EQ(r.value().walls_read, 1u);
  expect_format_valid(plan);
}

TEST(IfcShapes, AnUprightArchedProfileIsWallsWithSlopedTopsWithinTheTolerance) {
  // A half disc of radius 2 standing on the x axis, swept 0.3 m along y: the profile's x is
  // up (the position's x axis is world z), its y along world x.
  const std::string text = ifc_text(
      "#10=IFCCARTESIANPOINT((0.,-2.));\n#11=IFCCARTESIANPOINT((0.,2.));\n"
      "#12=IFCPOLYLINE((#10,#11));\n#13=IFCCARTESIANPOINT((0.,0.));\n"
      "#14=IFCAXIS2PLACEMENT2D(#13,$);\n#15=IFCCIRCLE(#14,2.);\n"
      "#16=IFCTRIMMEDCURVE(#15,(#11),(#10),.F.,.CARTESIAN.);\n"
      "#17=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.T.,#12);\n"
      "#18=IFCCOMPOSITECURVESEGMENT(.CONTINUOUS.,.T.,#16);\n"
      "#19=IFCCOMPOSITECURVE((#17,#18),.F.);\n"
      "#20=IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,#19);\n"
      "#21=IFCDIRECTION((0.,1.,0.));\n#22=IFCAXIS2PLACEMENT3D(#1,#21,#4);\n"
      "#23=IFCEXTRUDEDAREASOLID(#20,#22,#4,0.3);\n"
      "#24=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#23));\n"
      "#25=IFCPRODUCTDEFINITIONSHAPE($,$,(#24));\n"
      "#26=IFCWALL('0123456789abcdefghijkl',$,'arch',$,$,#3,#25,$,$);\n");
  const Result<IfcImport> r = import_ifc_text(text, "arch.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  ASSERT_GT(plan.walls.size(), 4u);
  double area = 0.0, highest = 0.0;
  for (const Wall& w : plan.walls) {
    EXPECT_NEAR(w.thickness, 0.3, 1e-6);
    EXPECT_NEAR(w.from.y, 0.15, 1e-6);  // the middle of the sweep
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    area += length * (w.height + w.height_at_end.value_or(w.height)) / 2;
    highest = std::max(highest, highest_height(w));
  }
  EXPECT_NEAR(highest, 2.0, 0.011);
  // The half disc's area, less what its chords cut off (each within 1 cm).
  EXPECT_NEAR(area, 3.14159265358979 * 2, 0.1);
  EXPECT_LT(area, 3.14159265358979 * 2);
  const IfcEntityTally& t = type_tally(r.value(), "IFCWALL");
  EXPECT_EQ(t.read, 1u);
  EXPECT_GT(t.distance, 0.001);
  EXPECT_LE(t.distance, 0.01);
  expect_format_valid(plan);
}

TEST(IfcShapes, AnOpeningVoidingASlabIsAHoleAndAnIndexedArcIsChords) {
  // A 6 x 4 slab 0.2 thick whose outline has a round end (an IfcArcIndex), voided by a 1 x 1
  // opening through it.
  const std::string text = ifc_text(
      "#10=IFCCARTESIANPOINTLIST2D(((0.,0.),(6.,0.),(8.,2.),(6.,4.),(0.,4.)));\n"
      "#11=IFCINDEXEDPOLYCURVE(#10,(IFCLINEINDEX((1,2)),IFCARCINDEX((2,3,4)),"
      "IFCLINEINDEX((4,5,1))),$);\n"
      "#12=IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,#11);\n"
      "#13=IFCCARTESIANPOINT((0.,0.,-0.2));\n#14=IFCAXIS2PLACEMENT3D(#13,$,$);\n"
      "#15=IFCEXTRUDEDAREASOLID(#12,#14,#4,0.2);\n"
      "#16=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#15));\n"
      "#17=IFCPRODUCTDEFINITIONSHAPE($,$,(#16));\n"
      "#18=IFCSLAB('0123456789abcdefghijkl',$,'floor',$,$,#3,#17,$,.FLOOR.);\n"
      "#20=IFCCARTESIANPOINT((2.5,1.5));\n#21=IFCAXIS2PLACEMENT2D(#20,$);\n"
      "#22=IFCRECTANGLEPROFILEDEF(.AREA.,$,#21,1.,1.);\n"
      "#23=IFCCARTESIANPOINT((0.,0.,-0.5));\n#24=IFCAXIS2PLACEMENT3D(#23,$,$);\n"
      "#25=IFCEXTRUDEDAREASOLID(#22,#24,#4,1.);\n"
      "#26=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#25));\n"
      "#27=IFCPRODUCTDEFINITIONSHAPE($,$,(#26));\n"
      "#28=IFCOPENINGELEMENT('1123456789abcdefghijkl',$,'well',$,$,#3,#27,$,.OPENING.);\n"
      "#29=IFCRELVOIDSELEMENT('2123456789abcdefghijkl',$,$,$,#18,#28);\n");
  const Result<IfcImport> r = import_ifc_text(text, "slab.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  ASSERT_EQ(plan.slabs.size(), 1u);
  const Slab& slab = plan.slabs[0];
  EXPECT_GT(slab.outline.size(), 10u);  // the half circle of radius 2 as chords
  double right = 0.0;
  for (const Point2& p : slab.outline) right = std::max(right, p.x);
  EXPECT_NEAR(right, 8.0, 1e-6);
  ASSERT_EQ(slab.holes.size(), 1u);
  EXPECT_EQ(slab.holes[0].size(), 4u);
  EXPECT_EQ(r.value().openings_read, 1u);
  EXPECT_EQ(r.value().source_openings, 1u);
  EXPECT_EQ(type_tally(r.value(), "IFCOPENINGELEMENT").approximated, 0u);
  EXPECT_NEAR(type_tally(r.value(), "IFCSLAB").distance, 0.001, 1e-12);
  expect_format_valid(plan);
}

TEST(IfcShapes, ACurtainWallIsAWallOverItsMembersAndPlates) {
  // Two mullions 0.05 x 0.15 and a glass plate between them, 2.5 m high, along y.
  std::string parts;
  auto box = [&](int id, double x, double y, double dx, double dy, const char* type) {
    const std::string n = std::to_string(id);
    parts += "#" + n + "1=IFCCARTESIANPOINT((" + std::to_string(x) + "," + std::to_string(y) +
             "));\n#" + n + "2=IFCAXIS2PLACEMENT2D(#" + n + "1,$);\n#" + n +
             "3=IFCRECTANGLEPROFILEDEF(.AREA.,$,#" + n + "2," + std::to_string(dx) + "," +
             std::to_string(dy) + ");\n#" + n + "4=IFCEXTRUDEDAREASOLID(#" + n +
             "3,#2,#4,2.5);\n#" + n + "5=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#" + n +
             "4));\n#" + n + "6=IFCPRODUCTDEFINITIONSHAPE($,$,(#" + n + "5));\n#" + n +
             "7=" + type + "('" + n + "23456789abcdefghijkl',$,$,$,$,#3,#" + n + "6,$);\n";
  };
  box(10, 0.0, 0.0, 0.15, 0.05, "IFCMEMBER");
  box(11, 0.0, 3.0, 0.15, 0.05, "IFCMEMBER");
  box(12, 0.0, 1.5, 0.02, 2.95, "IFCPLATE");
  const std::string text =
      ifc_text(parts +
               "#90=IFCCURTAINWALL('9123456789abcdefghijkl',$,'glass',$,$,#3,$,$);\n"
               "#91=IFCRELAGGREGATES('8123456789abcdefghijkl',$,$,$,#90,(#107,#117,#127));\n");
  const Result<IfcImport> r = import_ifc_text(text, "curtain.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  ASSERT_EQ(plan.walls.size(), 1u);
  const Wall& w = plan.walls[0];
  EXPECT_NEAR(w.thickness, 0.15, 1e-6);
  EXPECT_NEAR(w.height, 2.5, 1e-6);
  EXPECT_NEAR(std::hypot(w.to.x - w.from.x, w.to.y - w.from.y), 3.05, 1e-6);
  EXPECT_NEAR(w.from.x, 0.0, 1e-6);
  EXPECT_EQ(type_tally(r.value(), "IFCCURTAINWALL").read, 1u);
  EXPECT_EQ(type_tally(r.value(), "IFCMEMBER").read, 2u);
  EXPECT_EQ(type_tally(r.value(), "IFCPLATE").read, 1u);
  EXPECT_EQ(r.value().source_walls, 1u);
  EXPECT_EQ(r.value().walls_read, 1u);
  bool said = false;
  for (const Diagnostic& d : r.value().warnings.items)
    said |= d.message.find("a curtain wall is imported as a solid wall") != std::string::npos;
  EXPECT_TRUE(said);
  expect_format_valid(plan);
}

TEST(IfcShapes, AMappedItemIsPlacedByItsTransformationOperatorAndTheSiteByItsAngles) {
  // A 10 x 0.2 x 3 m wall mapped turned a quarter (its x along world y), doubled, to (1, 2);
  // the site at 51.5 N 0.125 W, north 45 degrees counter-clockwise from +y.
  const std::string text = ifc_text(
      "#10=IFCCARTESIANPOINT((5.,0.));\n#11=IFCAXIS2PLACEMENT2D(#10,$);\n"
      "#12=IFCRECTANGLEPROFILEDEF(.AREA.,$,#11,10.,0.2);\n"
      "#13=IFCEXTRUDEDAREASOLID(#12,#2,#4,3.);\n"
      "#14=IFCSHAPEREPRESENTATION($,'Body','SweptSolid',(#13));\n"
      "#15=IFCREPRESENTATIONMAP(#2,#14);\n#16=IFCDIRECTION((0.,1.,0.));\n"
      "#17=IFCCARTESIANPOINT((1.,2.,0.));\n"
      "#18=IFCCARTESIANTRANSFORMATIONOPERATOR3D(#16,$,#17,2.,$);\n"
      "#19=IFCMAPPEDITEM(#15,#18);\n"
      "#20=IFCSHAPEREPRESENTATION($,'Body','MappedRepresentation',(#19));\n"
      "#21=IFCPRODUCTDEFINITIONSHAPE($,$,(#20));\n"
      "#22=IFCWALL('0123456789abcdefghijkl',$,'mapped',$,$,#3,#21,$,$);\n"
      "#30=IFCDIRECTION((-1.,1.));\n"
      "#31=IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-05,#2,#30);\n"
      "#32=IFCSITE('1123456789abcdefghijkl',$,'site',$,$,#3,$,$,.ELEMENT.,(51,30,0,0),"
      "(0,-7,-30,0),0.,$,$);\n");
  const Result<IfcImport> r = import_ifc_text(text, "mapped.ifc");
  ASSERT_TRUE(r.ok()) << r.error();
  const Plan& plan = r.value().plan;
  ASSERT_EQ(plan.walls.size(), 1u);
  const Wall& w = plan.walls[0];
  EXPECT_NEAR(w.thickness, 0.4, 1e-6);
  EXPECT_NEAR(w.height, 6.0, 1e-6);
  EXPECT_NEAR(std::min(w.from.y, w.to.y), 2.0, 1e-6);
  EXPECT_NEAR(std::max(w.from.y, w.to.y), 22.0, 1e-6);
  EXPECT_NEAR(w.from.x, 1.0, 1e-6);
  EXPECT_NEAR(w.to.x, 1.0, 1e-6);
  ASSERT_TRUE(plan.site.location.has_value());
  EXPECT_NEAR(plan.site.location->latitude, 51.5, 1e-9);
  EXPECT_NEAR(plan.site.location->longitude, -0.125, 1e-9);
  EXPECT_EQ(plan.site.location->utc_offset, 0.0);
  EXPECT_NEAR(plan.site.north.value_or(0.0), 45.0, 1e-9);
  expect_format_valid(plan);
}

}  // namespace
}  // namespace roomcad
