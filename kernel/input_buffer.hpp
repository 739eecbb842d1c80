#pragma once
// The stream buffer a reader reads an input path through: a regular file's, or, for a
// FIFO, the descriptor that waited for its writer (kernel/fifo_wait.hpp), so an input
// FIFO nobody writes fails after DTLAB_FIFO_WAIT seconds instead of blocking the open.
#include <ext/stdio_filebuf.h>  // libstdc++: a stream buffer over a descriptor

#include <fstream>
#include <ios>
#include <memory>
#include <string>

#include "kernel/fifo_wait.hpp"
#include "kernel/input_error.hpp"

namespace dtlab {

// Throws InputError(path, 0, "cannot open file") when the path cannot be read.
inline std::unique_ptr<std::filebuf> open_input_buffer(const std::string& path) {
  FifoWriterWait fifo(path);
  if (fifo.fd() >= 0)
    return std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fifo.release(), std::ios::in | std::ios::binary,
                                                            std::size_t{1} << 16);
  auto file = std::make_unique<std::filebuf>();
  if (!file->open(path, std::ios::in | std::ios::binary)) throw InputError(path, 0, "cannot open file");
  return file;
}

}  // namespace dtlab
