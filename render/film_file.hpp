// A render's EXR is also the film it was resolved from: besides R, G, B it holds the film's sums
// (kernels/film.h: each pixel's sum of finite samples, its count of non-finite ones, the sum of
// their squares, and what was splatted onto it) and, in its metadata, the sample indices it holds ("sample_ranges"). Parts of
// one render over disjoint sample ranges merge into the render one run over all of them would have
// made (dtoadq merge), and a render continues from its file with the indices that follow (--resume).
#pragma once

#include <string>
#include <vector>

#include "film/image_metadata.hpp"
#include "film/image_output.hpp"
#include "render/film_readback.hpp"
#include "render/sample_ranges.hpp"

namespace lab::render {

struct FilmFile {
    std::string path;
    int width = 0, height = 0;
    FilmReadback film;
    SampleRanges ranges;
    film::ImageMetadata metadata;
};

// The film's buffers as EXR channels: film.sum.{R,G,B}, film.nonfinite, film.splat.{R,G,B},
// film.squares.{R,G,B}. A merge adds the squares as it adds the sums, so the merged film's
// variance (resolve_variance) is the whole render's.
std::vector<film::ImageChannel> film_channels(const FilmReadback& film);

// Reads a render's EXR with its film; throws lab::InputError naming the file and the channel or
// metadata field that is missing or bad (an EXR not written by a render has no film channels).
FilmFile read_film_file(const std::string& path);

// Throws lab::InputError(part.path, field, ...) unless `part` is a part of the render that
// `reference` (named `reference_name` in the message) describes: the same size and every metadata
// field equal except those that differ between parts of one render (samples, time, device,
// statistics, the PNG's tone map).
void check_same_render(const std::string& reference_name, const film::ImageMetadata& reference, int width, int height, const FilmFile& part);

// Parts of one render over disjoint sample ranges, summed: the film one run over all their
// samples would have made, to float rounding (a sum's order differs). Throws lab::InputError
// naming the part that does not belong or whose samples another part holds too.
FilmFile merge_film_files(const std::vector<FilmFile>& parts);

}  // namespace lab::render
