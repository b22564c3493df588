#include "common/core/user_texture.hpp"

#include "common/core/error.hpp"
#include "common/core/textures.hpp"

namespace ts {
void UserTexture::addOption(Options& o, const std::string& instead) {
  o.addFile("texture", &path_,
            std::string("your picture (") + kTextureFormats + ") instead of " + instead +
                "; or drop a file on the window",
            [this](const std::string& v) {
              if (v.empty()) throw Error("--texture: the file name is empty");
              file_ = fileTexture(v);  // throws "<path>: <what is wrong>"; the old picture stays
            });
}

const Image& UserTexture::image() const {
  static const Image kNone;
  return file_.image ? *file_.image : kNone;
}

TextureDesc UserTexture::orDefault(const TextureDesc& fallback) const {
  if (path_.empty()) return fallback;
  TextureDesc t = fallback;
  t.name = file_.name;
  t.params = file_.params;
  t.image = file_.image;
  t.mipLevels = nullptr;
  t.glTexture = 0;
  return t;
}
}  // namespace ts
