#pragma once
/// Keeps VTK from printing its own error text while Viscera reads a file: the reader's failure
/// is reported once, as a typed error naming the file, instead of pages of pipeline dumps.

namespace viscera::core {

/// Turns VTK's global warning and error display off for its lifetime and restores the previous
/// setting afterwards. Not for concurrent use from several threads.
class ScopedVtkSilence {
 public:
  ScopedVtkSilence();
  ~ScopedVtkSilence();
  ScopedVtkSilence(const ScopedVtkSilence&) = delete;
  ScopedVtkSilence& operator=(const ScopedVtkSilence&) = delete;

 private:
  int previous_;
};

}  // namespace viscera::core
