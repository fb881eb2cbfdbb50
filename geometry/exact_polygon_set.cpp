// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/exact_polygon_set.h"

#include <iterator>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>

namespace roomcad::detail {

struct ExactPolygonSet::Impl {
  CGAL::Polygon_set_2<CGAL::Epeck> set;
};

ExactPolygonSet::ExactPolygonSet() : impl_(std::make_unique<Impl>()) {}

ExactPolygonSet::ExactPolygonSet(const ExactPolygon& polygon)
    : impl_(std::make_unique<Impl>(Impl{CGAL::Polygon_set_2<CGAL::Epeck>(polygon)})) {}

ExactPolygonSet::ExactPolygonSet(const ExactPolygonWithHoles& area)
    : impl_(std::make_unique<Impl>(Impl{CGAL::Polygon_set_2<CGAL::Epeck>(area)})) {}

ExactPolygonSet::ExactPolygonSet(ExactPolygonSet&&) noexcept = default;
ExactPolygonSet& ExactPolygonSet::operator=(ExactPolygonSet&&) noexcept = default;
ExactPolygonSet::~ExactPolygonSet() = default;

void ExactPolygonSet::join(const std::vector<ExactPolygon>& polygons,
                           const std::vector<ExactPolygonWithHoles>& areas) {
  if (polygons.empty() && areas.empty()) return;
  impl_->set.join(polygons.begin(), polygons.end(), areas.begin(), areas.end());
}

void ExactPolygonSet::intersection(const ExactPolygonSet& other) {
  impl_->set.intersection(other.impl_->set);
}

void ExactPolygonSet::difference(const ExactPolygonSet& other) {
  impl_->set.difference(other.impl_->set);
}

bool ExactPolygonSet::is_empty() const { return impl_->set.is_empty(); }

std::vector<ExactPolygonWithHoles> ExactPolygonSet::polygons_with_holes() const {
  std::vector<ExactPolygonWithHoles> areas;
  impl_->set.polygons_with_holes(std::back_inserter(areas));
  return areas;
}

}  // namespace roomcad::detail
