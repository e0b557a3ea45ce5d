// htx compare: PSNR, largest channel difference and number of differing pixels of two images.
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/metrics.hpp"

namespace htx {

void register_compare(CLI::App& app) {
  struct Args {
    std::string a, b;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("compare", "Compare two images: PSNR, max channel difference, differing pixels");
  cmd->add_option("first", args->a, "first image (PNG)")->required()->check(CLI::ExistingFile);
  cmd->add_option("second", args->b, "second image (PNG)")->required()->check(CLI::ExistingFile);
  cmd->callback([args] {
    const ImageDiff d = compare_images(load_image(args->a), load_image(args->b));
    std::cout << "psnr_db " << (std::isfinite(d.psnr_db) ? std::to_string(d.psnr_db) : std::string("inf"))
              << "\nmax_channel_diff " << d.max_channel_diff << "\ndiffering_pixels " << d.differing_pixels
              << "\n";
  });
}

}  // namespace htx
