#include "core/zstd_frame.h"

#include <zstd.h>

#include <memory>

#include "core/error.h"

namespace maquette {

void append_zstd_frame(std::string_view content, int level, std::string& out) {
  const std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> z(ZSTD_createCCtx(), &ZSTD_freeCCtx);
  if (!z) throw Error("zstd compression failed: no context");
  ZSTD_CCtx_setParameter(z.get(), ZSTD_c_compressionLevel, level);
  ZSTD_CCtx_setParameter(z.get(), ZSTD_c_checksumFlag, 1);
  ZSTD_CCtx_setParameter(z.get(), ZSTD_c_contentSizeFlag, 1);
  const size_t at = out.size();
  out.resize(at + ZSTD_compressBound(content.size()));
  const size_t size =
      ZSTD_compress2(z.get(), out.data() + at, out.size() - at, content.data(), content.size());
  if (ZSTD_isError(size)) {
    out.resize(at);
    throw Error(std::string("zstd compression failed: ") + ZSTD_getErrorName(size));
  }
  out.resize(at + size);
}

std::string zstd_frame_content(std::string_view frame) {
  const unsigned long long declared = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (declared == ZSTD_CONTENTSIZE_ERROR || declared == ZSTD_CONTENTSIZE_UNKNOWN)
    throw Error("not a zstd frame with its content size");
  if (const size_t size = ZSTD_findFrameCompressedSize(frame.data(), frame.size());
      ZSTD_isError(size))
    throw Error(std::string("zstd frame: ") + ZSTD_getErrorName(size));
  else if (size != frame.size())
    throw Error(std::to_string(frame.size() - size) + " bytes after the zstd frame");
  const std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> d(ZSTD_createDCtx(), &ZSTD_freeDCtx);
  if (!d) throw Error("zstd frame: no decompression context");
  std::string out;
  ZSTD_inBuffer in{frame.data(), frame.size(), 0};
  const size_t chunk = ZSTD_DStreamOutSize();
  for (;;) {
    const size_t at = out.size();
    out.resize(at + chunk);
    ZSTD_outBuffer o{out.data() + at, chunk, 0};
    const size_t left = ZSTD_decompressStream(d.get(), &o, &in);
    if (ZSTD_isError(left)) throw Error(std::string("zstd frame: ") + ZSTD_getErrorName(left));
    out.resize(at + o.pos);
    if (out.size() > declared) throw Error("the zstd frame holds more than its content size");
    if (left == 0) break;  // the frame is whole and its checksum verified
    if (in.pos == in.size && o.pos < chunk) throw Error("the zstd frame is truncated");
  }
  if (out.size() != declared)
    throw Error("the zstd frame holds " + std::to_string(out.size()) + " bytes, not the " +
                std::to_string(declared) + " it declares");
  return out;
}

}  // namespace maquette
