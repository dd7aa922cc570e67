// The streams of hinge eval / oracle (tools/hinge_stream.hpp).
#include "hinge_stream.hpp"

#include <stdexcept>

namespace hinge::tools {

HingeStream::HingeStream(std::string input, std::string output, std::string what)
    : input_(std::move(input)), output_(std::move(output)), what_(std::move(what)) {}

bool HingeStream::open() {
  if (!input_.empty() && input_ != "-") {
    file_in_.open(input_);
    if (!file_in_) {
      std::cerr << "hinge " << what_ << ": cannot read " << input_ << "\n";
      return false;
    }
    in_ = &file_in_;
  }
  try {
    if (!output_.empty() && output_ != "-") out_ = &file_out_.emplace(output_).stream();
  } catch (const std::exception& e) {
    std::cerr << "hinge " << what_ << ": " << e.what() << "\n";
    return false;
  }
  return true;
}

int HingeStream::finish() {
  if (in_->bad()) {
    std::cerr << "hinge " << what_ << ": reading " << (input_.empty() ? "standard input" : input_) << " failed\n";
    return exit_invalid_input;
  }
  try {
    out_->flush();
    if (!*out_) throw std::runtime_error("writing the output failed");
    if (file_out_) file_out_->commit();
  } catch (const std::exception& e) {
    std::cerr << "hinge " << what_ << ": " << e.what() << "\n";
    return exit_invalid_input;
  }
  return exit_done;
}

}  // namespace hinge::tools
