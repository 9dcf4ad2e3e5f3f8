// The animation as a GIF, made by Debian's ffmpeg program (Debian's VTK has no video writer).
// Frames reach ffmpeg as raw RGB, shrunk by a whole factor to about 640 pixels wide (a box
// average: no PNG is decoded again and no filter resamples); a palette gathered from every frame
// keeps the colours clean. Without ffmpeg the PNG frames stand alone and the caller is told why
// there is no GIF.
#pragma once

#include <sys/types.h>

#include <string>

class vtkImageData;

namespace plastica::render {

struct AnimationResult {
    bool written = false;
    std::string message; // what happened, for the user
};

// The whole factor that brings a frame `width` pixels wide to about 640.
int animation_shrink(int width);
// A frame shrunk by `factor` (the mean of each factor × factor block), RGB rows from the top.
std::string animation_pixels(vtkImageData* frame, int factor);

// Two passes of ffmpeg: the palette is gathered from the frames as they come (streamed, in
// order), and the GIF is made from the frames kept in one raw file once the last is drawn.
// Frame k of the sequence is written to that file at k × frame_bytes() by whichever process drew
// it (write_animation_frame).
class GifWriter {
public:
    GifWriter(std::string gif_path, int width, int height, int frames_per_second = 12);
    ~GifWriter();
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;

    const std::string& frame_file() const { return frames_; }
    std::size_t frame_bytes() const { return frame_bytes_; }
    // Starts the palette pass; call it after the drawing processes have been started, so that they
    // do not hold its pipe open.
    void start();
    // Frame k is in the frame file: to the palette pass, in the order of the sequence.
    void add(std::size_t k);
    // Makes the GIF from the frames 0 … count − 1 and moves it into place.
    AnimationResult finish(std::size_t count);

private:
    std::string gif_path_, temporary_, palette_, frames_;
    int width_, height_, frames_per_second_;
    std::size_t frame_bytes_ = 0;
    pid_t palette_pass_ = -1;
    int palette_input_ = -1;
    std::string failure_;     // why there is no GIF, once known
    void (*previous_sigpipe_)(int) = nullptr;
};

// Writes frame k (animation_pixels' bytes) into a GifWriter's frame file.
void write_animation_frame(const std::string& frame_file, std::size_t k, const std::string& rgb);

} // namespace plastica::render
