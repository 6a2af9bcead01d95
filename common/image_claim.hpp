// What an image file's header may claim before the lab allocates for its pixels. A header is a
// few bytes anyone can write: one that says 32768 x 16384 would have the reader allocate gigabytes
// before the first pixel shows the file to be a lie. So the claim is checked against the file and
// the machine first, each failure one line naming the file and its size:
//  - the file must hold at least the fewest bytes its format can encode that many pixels in
//    (minimum_encoded_bytes), and
//  - the floats the reader will hold must fit in half of the machine's memory.
#pragma once

#include <cstdint>
#include <string>

#include "common/image_codec.hpp"

namespace lab::codec {

// The fewest bytes in which `format` (OpenImageIO's name) can encode width x height pixels of
// `channels` channels; 0 for a format this does not bound.
//  - "hdr": a Radiance scanline of 8 to 32767 pixels in the run-length encoding OpenImageIO reads is
//    a 4-byte mark and, per component (4), runs of at most 127 equal bytes in 2 bytes each;
//    any other width is stored flat, 4 bytes a pixel.
//  - "openexr": its most compressible encoding is DWA's for a flat block, one half-float DC value
//    per 8 x 8 pixels and channel, through zlib, which no input shrinks more than 1032:1.
//  - "png": a filter byte a row and a byte a sample at the least, through zlib.
uint64_t minimum_encoded_bytes(const std::string& format, int width, int height, int channels);

// The machine's physical memory in bytes (sysconf); 0 when it cannot be told.
uint64_t physical_memory_bytes();

// Throws lab::InputError ("PATH: size: ...") when `header`'s width x height cannot be what a file of
// `file_bytes` bytes holds, or when reading it as `floats_per_pixel` floats a pixel would take more
// than half of `memory_bytes` (0: unbounded).
void check_image_claim(const std::string& path, const Header& header, uint64_t file_bytes, int floats_per_pixel, uint64_t memory_bytes);

// The same for the file at `path` as it is (its size, 0 when it cannot be told) on this machine
// (physical_memory_bytes): what a reader calls between opening a file and allocating its pixels.
void check_image_file_claim(const std::string& path, const Header& header, int floats_per_pixel);

}  // namespace lab::codec
