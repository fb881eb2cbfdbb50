// SPDX-License-Identifier: GPL-3.0-or-later
// Validation of the imported Sweet Home 3D homes: every error left is a real problem of the home
// as drawn (listed below with why), never one the import made.
#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "import/sh3d_test_data.h"
#include "validation/room_labels.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

struct Problem {
  Code code = Code::wall_overlap;
  std::vector<std::string> objects;  ///< sorted
  auto operator<=>(const Problem&) const = default;
};

/// Long ids of the eTeks files, shortened for the table below.
std::string item(const char* uuid) { return std::string("doorOrWindow-") + uuid; }

/// The real problems of each flat, found by looking at the geometry in the XML.
std::set<Problem> real_problems_of_flat(const std::string& home) {
  if (home == "1-BedroomApartment")
    return {// wall4 and wall5 are drawn along one line and overlap for 14 cm.
            {Code::wall_overlap, {"wall4", "wall5"}},
            // Two doors side by side in wall11 overlap by 6 mm.
            {Code::opening_overlap,
             {item("f5d05573-b541-437d-ba8c-fd55146c8f41"),
              item("f663a32a-f23d-4fbc-9ccb-44f9d73afc87")}}};
  if (home == "2-BedroomApartment")
    return {
        // A thin slanted wall (wall2) is drawn inside the outer wall27, under a window.
        {Code::wall_overlap, {"wall2", "wall27"}},
        {Code::opening_blocked, {item("04bc5b8c-a3a1-4a67-9daf-d96bd088bbaf"), "wall2", "wall27"}},
        {Code::opening_blocked,
         {item("04bc5b8c-a3a1-4a67-9daf-d96bd088bbaf-2"), "wall2", "wall27"}},
        // A door frame and a French window fill the same hole of wall22.
        {Code::opening_overlap,
         {item("64b11339-e657-4ca1-9406-3c588ed826a8"),
          item("757b71b6-7eef-462c-879b-f67dc36de6d5")}}};
  if (home == "3-BedroomApartment")
    return {// A low wall (wall25) pokes 1 cm into the corner of wall21 and wall28.
            {Code::wall_overlap, {"wall21", "wall25"}},
            {Code::wall_overlap, {"wall25", "wall28"}},
            // wall38 is a 3 mm piece drawn over the ends of wall29 and wall39.
            {Code::wall_overlap, {"wall29", "wall38"}},
            {Code::wall_overlap, {"wall29", "wall39"}},
            {Code::wall_overlap, {"wall38", "wall39"}}};
  if (home == "ApartmentWithBowWindow")
    return {
        // (wall36 starts and ends at the same point: the import leaves it out and says so.)
        // wall18 is drawn back over wall13, along the same 2.4 m.
        {Code::wall_overlap, {"wall13", "wall18"}},
        // A thin wall (wall42) pokes 4 to 6 cm into the corner of wall8 and wall41.
        {Code::wall_overlap, {"wall42", "wall8"}},
        {Code::wall_overlap, {"wall41", "wall42"}},
        // A window of wall8 is drawn 7 cm into the end of wall1.
        {Code::opening_blocked, {item("7778267d-5a42-4a48-979a-7e90c6e93696"), "wall1", "wall8"}}};
  return {};
}

/// The real problems of each house, found the same way.
std::set<Problem> real_problems_of_house(const std::string& home) {
  if (home == "2-BedroomHouseWithBasement")
    return {
        // Two 4 cm walls drawn end to end overlap for 2 cm, 2 mm apart side to side.
        {Code::wall_overlap, {"wall18", "wall19"}},
        // A door straddles the joint of wall4 and wall14, which meet at a 0.2 degree kink
        // (each piece's hole is grazed by the other wall), and wall2 ends 1.7 mm into it.
        {Code::opening_blocked, {item("eb07e089-7798-478a-922f-9309c8f437cf"), "wall14", "wall4"}},
        {Code::opening_blocked,
         {item("eb07e089-7798-478a-922f-9309c8f437cf-2"), "wall14", "wall4"}},
        {Code::opening_blocked, {item("eb07e089-7798-478a-922f-9309c8f437cf-2"), "wall2", "wall4"}},
        // The basement's 4 cm walls wall17 and wall19 rise to 2.62 m, 12 cm above the first
        // floor's base, into the mitred outer corners of the walls around them: wall1 and
        // wall29 (ground) and wall5 and wall25 (first floor) at the west, wall0 and wall1,
        // wall7 and wall27 at the east.
        {Code::wall_overlap, {"wall1", "wall17"}},
        {Code::wall_overlap, {"wall17", "wall29"}},
        {Code::wall_overlap, {"wall17", "wall5"}},
        {Code::wall_overlap, {"wall17", "wall25"}},
        {Code::wall_overlap, {"wall0", "wall19"}},
        {Code::wall_overlap, {"wall1", "wall19"}},
        {Code::wall_overlap, {"wall19", "wall7"}},
        {Code::wall_overlap, {"wall19", "wall27"}}};
  if (home == "3-BedroomHouseWithAttic")
    return {// Walls drawn 1 to 14 mm into a neighbour, where no T or corner join applies.
            {Code::wall_overlap, {"wall11", "wall30"}},
            {Code::wall_overlap, {"wall16", "wall34"}},
            {Code::wall_overlap, {"wall16", "wall35"}},
            {Code::wall_overlap, {"wall16", "wall53"}},
            {Code::wall_overlap, {"wall31", "wall45"}},
            {Code::wall_overlap, {"wall35", "wall53"}},
            {Code::wall_overlap, {"wall47", "wall54"}},
            // The mitred corner of wall29 reaches 0.9 mm into the side of wall31.
            {Code::wall_overlap, {"wall29", "wall31"}}};
  if (home == "3-BedroomHouseWithMezzanine")
    return {// wall27 pokes 1 cm into wall25 and wall59, off their centre lines.
            {Code::wall_overlap, {"wall25", "wall27"}},
            {Code::wall_overlap, {"wall27", "wall59"}},
            // wall63 leans by 2 mm over 5.6 m, so wall64's end is 1 micrometre inside it.
            {Code::wall_overlap, {"wall63", "wall64"}},
            // The mitred corner of wall43 reaches 0.3 mm into the thin wall57.
            {Code::wall_overlap, {"wall43", "wall57"}},
            // Two fixed windows of wall57 overlap by 16 cm.
            {Code::opening_overlap,
             {item("b808eea4-6043-418c-8965-14935f4412bf"),
              item("d7c1f1d3-d2ae-4a94-bdf8-7fccba0b117d")}}};
  if (home == "4-BedroomHouse")
    return {
        // A door drawn into the corner where wall1 and wall33 meet wall2.
        {Code::opening_blocked, {item("b2b2dd23-d20c-4009-91ea-cae050f3f8dd"), "wall1", "wall2"}},
        {Code::opening_blocked, {item("b2b2dd23-d20c-4009-91ea-cae050f3f8dd"), "wall2", "wall33"}}};
  return {};
}

/// Studio and the edge-case Sample validate without errors.
std::set<Problem> real_problems(const std::string& home) {
  std::set<Problem> problems = real_problems_of_flat(home);
  problems.merge(real_problems_of_house(home));
  return problems;
}

/// The points of each `<room>` of the home, in metres with y north (centimetres times 0.01, as
/// the importer reads them), by room id.
std::map<std::string, std::set<std::pair<double, double>>> room_points(const std::string& xml) {
  std::map<std::string, std::set<std::pair<double, double>>> rooms;
  const std::regex room("<room id='([^']*)'[^>]*>([\\s\\S]*?)</room>");
  const std::regex point("<point x='([^']*)' y='([^']*)'/>");
  for (std::sregex_iterator r(xml.begin(), xml.end(), room), end; r != end; ++r) {
    const std::string body = (*r)[2];
    for (std::sregex_iterator q(body.begin(), body.end(), point); q != end; ++q)
      rooms[(*r)[1]].insert({std::stod((*q)[1]) * 0.01, 0.0 - std::stod((*q)[2]) * 0.01});
  }
  return rooms;
}

/// Whether slab `id` is the floor or ceiling of a room of the home, with the room's points as
/// drawn: then an overlap of two such slabs is the rooms' own, drawn overlapping.
bool is_room_as_drawn(const Plan& plan, const std::string& id,
                      const std::map<std::string, std::set<std::pair<double, double>>>& rooms) {
  const std::string room = id.ends_with("-ceiling") ? id.substr(0, id.size() - 8) : id;
  for (const Slab& s : plan.slabs) {
    if (s.id != id) continue;
    std::set<std::pair<double, double>> points;
    for (const Point2& p : s.outline) points.insert({p.x, p.y});
    return rooms.contains(room) && rooms.at(room) == points;
  }
  return false;
}

TEST(Sh3dValidation, SlabsOverlapOnlyWhereTheirRoomsAreDrawnOverlapping) {
  std::size_t overlaps = 0;
  for (const fs::path& home : all_homes()) {
    SCOPED_TRACE(home.filename().string());
    const auto rooms = room_points(read_text(home));
    const Plan plan = import_or_fail(home).plan;
    for (const Diagnostic& d : validate(plan).items) {
      if (d.code != Code::slab_overlap) continue;
      ++overlaps;
      ASSERT_EQ(d.objects.size(), 2u);
      for (const std::string& id : d.objects) EXPECT_TRUE(is_room_as_drawn(plan, id, rooms)) << id;
    }
  }
  EXPECT_GT(overlaps, 0u);  // the homes have rooms drawn over one another (a few mm to metres)
}

TEST(Sh3dValidation, OnlyTheHomesOwnProblemsAreErrors) {
  for (const fs::path& home : all_homes()) {
    const std::string name = home.stem().stem().string();
    SCOPED_TRACE(name);
    const Plan plan = import_or_fail(home).plan;
    std::set<Problem> errors;
    for (const Diagnostic& d : validate(plan).items) {
      // Slab overlaps are the rooms' own (SlabsOverlapOnlyWhereTheirRoomsAreDrawnOverlapping).
      if (d.severity != Severity::error || d.code == Code::slab_overlap) continue;
      Problem p{d.code, d.objects};
      std::ranges::sort(p.objects);
      errors.insert(p);
    }
    const std::set<Problem> expected = real_problems(name);
    for (const Problem& p : errors)
      EXPECT_TRUE(expected.contains(p))
          << "unexpected " << p.code << " " << ::testing::PrintToString(p.objects);
    for (const Problem& p : expected)
      EXPECT_TRUE(errors.contains(p))
          << "missing " << p.code << " " << ::testing::PrintToString(p.objects);
  }
}

// The homes' named rooms come across as `rooms` labels, each inside the room it names on its
// level; every room of the Studio and the 4-bedroom house that has a name gets it, and those
// named as baths, halls or corridors are not asked for a window.
TEST(Sh3dValidation, RoomNamesComeAcrossInsideTheirRooms) {
  for (const char* name : {"Studio", "4-BedroomHouse"}) {
    SCOPED_TRACE(name);
    const Sh3dImport imported =
        import_or_fail(kData / "eteks-example-homes" / (std::string(name) + ".Home.xml"));
    const Plan& plan = imported.plan;
    ASSERT_FALSE(plan.rooms.empty());
    std::vector<Room> rooms;
    for (const LevelRooms& level : find_rooms_by_level(plan))
      rooms.insert(rooms.end(), level.rooms.begin(), level.rooms.end());
    const std::vector<const RoomLabel*> labels = room_labels(rooms, plan);
    std::size_t named = 0;
    for (std::size_t r = 0; r < rooms.size(); ++r) named += labels[r] != nullptr;
    EXPECT_GE(named, plan.rooms.size() / 2) << named << " of " << rooms.size() << " rooms named";
    for (const Diagnostic& d : validate(plan).items)
      EXPECT_NE(d.code, Code::room_without_window) << d.message;
  }
  const Sh3dImport house =
      import_or_fail(kData / "eteks-example-homes" / "4-BedroomHouse.Home.xml");
  std::set<std::string> kinds;
  for (const RoomLabel& label : house.plan.rooms) kinds.insert(label.name);
  EXPECT_TRUE(kinds.contains("Kitchen") && kinds.contains("Corridor")) << kinds.size();
}

}  // namespace
}  // namespace roomcad
