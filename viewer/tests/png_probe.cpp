// png_probe FILE [RRGGBB MIN]...: checks a screenshot of the viewer. It must load, must
// not be blank (many colours, not all background), and must hold at least MIN pixels
// of each colour given (each channel within 24). One line on failure, exit 1.
#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2 || argc % 2) {
    std::fprintf(stderr, "usage: png_probe FILE [RRGGBB MIN]...\n");
    return 2;
  }
  int w = 0, h = 0, n = 0;
  unsigned char* p = stbi_load(argv[1], &w, &h, &n, 3);
  if (!p) {
    std::fprintf(stderr, "png_probe: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 1;
  }
  std::set<int> colours;
  for (int i = 0; i < w * h; ++i) colours.insert(p[3 * i] << 16 | p[3 * i + 1] << 8 | p[3 * i + 2]);
  int status = 0;
  if (colours.size() < 50) {
    std::fprintf(stderr, "png_probe: %s looks blank (%zu distinct colours)\n", argv[1], colours.size());
    status = 1;
  }
  for (int a = 2; a + 1 < argc; a += 2) {
    const long rgb = std::strtol(argv[a], nullptr, 16), least = std::atol(argv[a + 1]);
    const int r = int(rgb >> 16 & 255), g = int(rgb >> 8 & 255), b = int(rgb & 255);
    long count = 0;
    for (int i = 0; i < w * h; ++i)
      count += std::abs(p[3 * i] - r) <= 24 && std::abs(p[3 * i + 1] - g) <= 24 && std::abs(p[3 * i + 2] - b) <= 24;
    if (count < least) {
      std::fprintf(stderr, "png_probe: %s has %ld pixels of colour %s, fewer than %ld\n", argv[1], count, argv[a],
                   least);
      status = 1;
    }
  }
  stbi_image_free(p);
  if (status == 0)
    std::printf("png_probe: %s is %dx%d with %zu colours; every colour asked for is there\n", argv[1], w, h,
                colours.size());
  return status;
}
