// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/bcf_export.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <zip.h>

#include "io/ifc_guid.h"
#include "io/image_io.h"
#include "io/svg_writer.h"
#include "plan/plan_levels.h"
#include "render/render_request.h"
#include "render/renderer.h"
#include "solid/build_model.h"
#include "validation/report_tally.h"

namespace roomcad {
namespace {

constexpr std::string_view kXmlHead = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";

/// A file of the archive: its path and bytes.
struct Entry {
  std::string name;
  std::string bytes;
};

std::string title_of(const Diagnostic& d) {
  std::string objects;
  for (const std::string& o : d.objects) objects += (objects.empty() ? "" : ", ") + o;
  return fmt::format("{}{}{}", to_string(d.code), objects.empty() ? "" : ": ", objects);
}

std::string markup(const Diagnostic& d, const std::string& guid, const std::string& view_guid,
                   const BcfInput& in, bool closed, bool snapshot) {
  std::string description = d.message;
  if (!d.fix.empty()) description += " Fix: " + d.fix;
  description += fmt::format(" ({})", in.plan_file);
  return fmt::format(
      "{}<Markup>\n  <Topic Guid=\"{}\" TopicType=\"{}\" TopicStatus=\"{}\">\n"
      "    <Title>{}</Title>\n    <Labels>{}</Labels>\n    <Labels>{}</Labels>\n"
      "    <CreationDate>{}</CreationDate>\n    <CreationAuthor>roomcad</CreationAuthor>\n"
      "    <Description>{}</Description>\n  </Topic>\n"
      "  <Viewpoints Guid=\"{}\">\n    <Viewpoint>viewpoint.bcfv</Viewpoint>\n{}  </Viewpoints>\n"
      "</Markup>\n",
      kXmlHead, guid, d.severity == Severity::error ? "Error" : "Warning",
      closed ? "Closed" : "Open", escape_xml(title_of(d)), to_string(d.code),
      d.severity == Severity::error ? "error" : "warning", in.date, escape_xml(description),
      view_guid, snapshot ? "    <Snapshot>snapshot.png</Snapshot>\n" : "");
}

std::string xyz(std::string_view tag, double x, double y, double z) {
  return fmt::format("<{}><X>{}</X><Y>{}</Y><Z>{}</Z></{}>", tag, x, y, z, tag);
}

/// The box a finding is about: its `where`, else the box of its objects (walls' centre lines,
/// openings' spans along their walls, slabs' outlines); nullopt if it has neither.
std::optional<std::pair<Point2, Point2>> place_of(const Diagnostic& d, const Plan& plan) {
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  const auto add = [&](Point2 p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  };
  if (d.where) {
    add(d.where->min);
    add(d.where->max.value_or(d.where->min));
  } else {
    const auto wall_span = [&](const Wall& w, double from, double to) {
      const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
      if (!(length > 0)) return add(w.from);
      for (const double u : {from, to})
        add({w.from.x + (w.to.x - w.from.x) * u / length,
             w.from.y + (w.to.y - w.from.y) * u / length});
    };
    for (const std::string& id : d.objects) {
      for (const Wall& w : plan.walls)
        if (w.id == id) add(w.from), add(w.to);
      for (const Opening& o : plan.openings)
        if (o.id == id)
          if (const Wall* host = find_wall(plan, o.wall))
            wall_span(*host, o.offset, o.offset + o.width);
      for (const Slab& slab : plan.slabs)
        if (slab.id == id)
          for (const Point2& p : slab.outline) add(p);
    }
  }
  if (!(lo_x <= hi_x)) return std::nullopt;
  return std::pair{Point2{lo_x, lo_y}, Point2{hi_x, hi_y}};
}

/// A camera 45 degrees above a finding's place, from the south, far enough to see it whole.
struct TopicCamera {
  Vec3 eye, target;
};

/// @param level  the finding's level (item_levels), whose floor the camera looks at
std::optional<TopicCamera> camera_of(const Diagnostic& d, const Plan& plan,
                                     const std::string& level) {
  const auto place = place_of(d, plan);
  if (!place) return std::nullopt;
  const auto [lo, hi] = *place;
  const double cx = (lo.x + hi.x) / 2, cy = (lo.y + hi.y) / 2;
  const double reach = std::max({hi.x - lo.x, hi.y - lo.y, 2.0}) * 1.5;
  const double floor = level.empty() ? 0.0 : level_elevation(plan, level);
  return TopicCamera{{cx, cy - reach, floor + 1.0 + reach}, {cx, cy, floor + 1.0}};
}

std::string camera_xml(const std::optional<TopicCamera>& c) {
  if (!c) return "";
  const double s = std::sqrt(0.5);
  return fmt::format(
      "  <PerspectiveCamera>{}{}{}<FieldOfView>60</FieldOfView></PerspectiveCamera>\n",
      xyz("CameraViewPoint", c->eye.x, c->eye.y, c->eye.z), xyz("CameraDirection", 0.0, s, -s),
      xyz("CameraUpVector", 0.0, s, s));
}

/// The snapshot of a viewpoint: the model from its camera, 320 x 200, as PNG bytes.
std::string snapshot(const Model& model, const Plan& plan, const TopicCamera& c) {
  RenderRequest request;
  request.width = 320;
  request.height = 200;
  request.shadows = "off";
  request.eye = fmt::format("{},{},{}", c.eye.x, c.eye.y, c.eye.z);
  request.target = fmt::format("{},{},{}", c.target.x, c.target.y, c.target.z);
  request.fov = 60.0;
  const Result<RenderOptions> options = make_render_options(request, plan);
  if (!options) return {};
  FrameBuffers frame;
  render_model(model, options.value(), frame);
  const Result<std::string> png = png_bytes(frame.color);
  return png ? png.value() : std::string();
}

std::string viewpoint(const Diagnostic& d, const std::string& guid, const Plan& plan,
                      const std::optional<TopicCamera>& camera) {
  std::string components;
  for (const std::string& id : d.objects)
    if (const auto global = ifc_global_id_of(plan, id))
      components += fmt::format(
          "      <Component IfcGuid=\"{}\">\n        <AuthoringToolId>{}"
          "</AuthoringToolId>\n      </Component>\n",
          *global, escape_xml(id));
  return fmt::format(
      "{}<VisualizationInfo Guid=\"{}\">\n  <Components>\n    <Selection>\n{}    </Selection>\n"
      "    <Visibility DefaultVisibility=\"true\"/>\n  </Components>\n{}</VisualizationInfo>\n",
      kXmlHead, guid, components, camera_xml(camera));
}

/// The files of one finding's topic.
std::vector<Entry> topic(const Diagnostic& d, const std::string& identity, const std::string& level,
                         const BcfInput& in, const Model* model, bool closed) {
  const std::string guid = hashed_guid("topic:" + identity);
  const std::string view_guid = hashed_guid("viewpoint:" + identity);
  const std::optional<TopicCamera> camera = camera_of(d, *in.plan, level);
  std::string png = model && camera ? snapshot(*model, *in.plan, *camera) : std::string();
  std::vector<Entry> files{
      {guid + "/markup.bcf", markup(d, guid, view_guid, in, closed, !png.empty())},
      {guid + "/viewpoint.bcfv", viewpoint(d, view_guid, *in.plan, camera)}};
  if (!png.empty()) files.push_back({guid + "/snapshot.png", std::move(png)});
  return files;
}

/// The model of each level findings are on (the whole plan for ""), for the snapshots: a
/// finding's storey seen without the storeys above it. Levels whose model cannot be built
/// have none (their topics go without a snapshot).
std::map<std::string, std::optional<Model>> level_models(const Plan& plan,
                                                         const std::vector<std::string>& levels) {
  std::map<std::string, std::optional<Model>> models;
  for (const std::string& level : levels) {
    if (models.contains(level)) continue;
    std::optional<Model>& model = models[level];
    try {
      model.emplace(build_model(level.empty() ? plan : plan_of_level(plan, level), BuildOptions{}));
    } catch (const PreconditionError& e) {
      std::fprintf(stderr, "roomcad: no BCF snapshots of level '%s': %s\n", level.c_str(),
                   e.what());
    }
  }
  return models;
}

/// The zip of `entries`, deflated, every entry dated 1 January 1980 (the first date a zip
/// holds), so that the same entries give the same bytes.
Result<std::string> zip_bytes(const std::vector<Entry>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!buffer) return Result<std::string>::failure(Code::io_error, zip_error_strerror(&error));
  zip_source_keep(buffer);
  const std::unique_ptr<zip_source_t, decltype(&zip_source_free)> owned(buffer, zip_source_free);
  zip_t* archive = zip_open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (!archive) return Result<std::string>::failure(Code::io_error, zip_error_strerror(&error));
  constexpr time_t kEpoch = 315532800 + 12 * 3600;  // 1980-01-01 12:00 UTC: no time zone moves it
  for (const Entry& e : entries) {
    zip_source_t* data = zip_source_buffer(archive, e.bytes.data(), e.bytes.size(), 0);
    const zip_int64_t index =
        data ? zip_file_add(archive, e.name.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (data) zip_source_free(data);
      const std::string why = zip_strerror(archive);
      zip_discard(archive);
      return Result<std::string>::failure(Code::io_error, why);
    }
    zip_file_set_mtime(archive, zip_uint64_t(index), kEpoch, 0);
  }
  if (zip_close(archive) != 0) {
    const std::string why = zip_strerror(archive);
    zip_discard(archive);
    return Result<std::string>::failure(Code::io_error, why);
  }
  std::string bytes;
  if (zip_source_open(buffer) != 0) return Result<std::string>::failure(Code::io_error, "zip");
  char chunk[1 << 16];
  for (zip_int64_t n; (n = zip_source_read(buffer, chunk, sizeof chunk)) > 0;)
    bytes.append(chunk, std::size_t(n));
  zip_source_close(buffer);
  return bytes;
}

}  // namespace

std::string file_date_for_bcf(const std::string& path) {
  std::error_code error;
  const auto written = std::filesystem::last_write_time(path, error);
  if (error) return "1980-01-01T00:00:00Z";
  const auto seconds =
      std::chrono::time_point_cast<std::chrono::seconds>(std::chrono::file_clock::to_sys(written));
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", seconds);
}

Result<std::string> write_bcf_archive(const BcfInput& in) {
  std::vector<Entry> entries;
  entries.push_back({"bcf.version", std::string(kXmlHead) +
                                        "<Version VersionId=\"2.1\">\n  <DetailedVersion>2.1"
                                        "</DetailedVersion>\n</Version>\n"});
  const std::vector<std::string> ids = in.comparison ? in.comparison->ids : item_ids(*in.report);
  // Every finding of the report, then the baseline's fixed ones, each with its identity and level.
  struct Finding {
    const Diagnostic* item;
    const std::string* identity;
    std::string level;
    bool closed;
  };
  std::vector<Finding> findings;
  const std::vector<std::string> levels = item_levels(*in.report, *in.plan);
  for (std::size_t i = 0; i < in.report->items.size(); ++i)
    findings.push_back({&in.report->items[i], &ids[i], levels[i], false});
  if (in.comparison) {
    const std::vector<std::string> fixed_levels = item_levels(in.comparison->fixed, *in.plan);
    for (std::size_t i = 0; i < in.comparison->fixed.items.size(); ++i)
      findings.push_back(
          {&in.comparison->fixed.items[i], &in.comparison->fixed_ids[i], fixed_levels[i], true});
  }
  std::vector<std::string> used_levels;
  for (const Finding& f : findings) used_levels.push_back(f.level);
  const auto models =
      in.snapshots ? level_models(*in.plan, used_levels) : decltype(level_models(*in.plan, {})){};
  // Topics in parallel (a snapshot each), placed in finding order: the same bytes at any
  // thread count.
  std::vector<std::vector<Entry>> topics(findings.size());
  tbb::parallel_for(std::size_t{0}, findings.size(), [&](std::size_t k) {
    const Finding& f = findings[k];
    const auto model = models.find(f.level);
    const Model* built = model != models.end() && model->second ? &*model->second : nullptr;
    topics[k] = topic(*f.item, *f.identity, f.level, in, built, f.closed);
  });
  for (std::vector<Entry>& files : topics)
    for (Entry& e : files) entries.push_back(std::move(e));
  return zip_bytes(entries);
}

}  // namespace roomcad
