// SPDX-License-Identifier: GPL-3.0-or-later
// Object-id PNG and its JSON legend.
#include "io/id_image.h"

#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "io/image_io.h"

namespace roomcad {
namespace {

Color id_color(std::int32_t index) {
  const auto code = static_cast<std::uint32_t>(index + 1);
  return {static_cast<std::uint8_t>(code & 0xff), static_cast<std::uint8_t>((code >> 8) & 0xff),
          static_cast<std::uint8_t>((code >> 16) & 0xff)};
}

}  // namespace

RgbImage encode_object_ids(const ObjectIdImage& ids) {
  RgbImage image(ids.width, ids.height);
  for (std::size_t i = 0; i < ids.ids.size(); ++i) {
    const Color c = ids.ids[i] < 0 ? Color{0, 0, 0} : id_color(ids.ids[i]);
    image.pixels[3 * i] = c.r;
    image.pixels[3 * i + 1] = c.g;
    image.pixels[3 * i + 2] = c.b;
  }
  return image;
}

std::filesystem::path legend_path(const std::filesystem::path& png) {
  std::filesystem::path legend = png;
  if (png.extension() == ".json") return legend.replace_extension(".legend.json");
  return legend.replace_extension(".json");
}

Status write_object_ids(const ObjectIdImage& ids, const std::vector<std::string>& objects,
                        const std::filesystem::path& png) {
  nlohmann::ordered_json legend;
  legend["encoding"] = "index + 1 = red + 256 * green + 65536 * blue; black: no object";
  legend["objects"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    legend["objects"].push_back({{"index", i},
                                 {"id", objects[i]},
                                 {"color", to_string(id_color(static_cast<std::int32_t>(i)))}});
  }
  if (Status s = write_png(encode_object_ids(ids), png); !s.ok()) return s;
  return write_file_atomically(legend_path(png), legend.dump(2) + "\n");
}

}  // namespace roomcad
