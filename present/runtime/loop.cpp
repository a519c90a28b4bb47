#include "runtime/loop.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <future>
#include <optional>
#include <thread>

#include "runtime/synth.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"

namespace velocity::realtime {

namespace {

using Clock = std::chrono::steady_clock;

// Set by the handler, read by the loop. The kernel may run the handler on any
// thread (the render thread too), so a volatile sig_atomic_t, which is only
// safe within one thread, will not do; a lock-free atomic is safe in a signal
// handler (C++17 [support.signal]) and between threads.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int sig) {
  const int saved_errno = errno;  // the interrupted code's
  g_stop_signal.store(sig);
  std::signal(sig, SIG_DFL);  // a second one ends the program at once
  errno = saved_errno;
}

// The whole file or none: PNGs are written next to their name and renamed.
void write_png_whole(const std::string& path, const Image& image) {
  std::string part = path + ".part";
  write_png(part, image);
  std::error_code ec;
  std::filesystem::rename(part, path, ec);
  if (ec) throw Error("cannot write " + path + ": " + ec.message());
}

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The render thread's side: owns the renderer; one frame at a time.
struct RenderJob {
  FrameDescription frame;
  int width = 0, height = 0;
  std::string stats_text;  // the overlay's frame-rate line ("" when off)
};

struct Rendered {
  Image image;
  double ms = 0;
  std::string screenshot;
  Image clean;  // the screenshot without the 2D layer, when it asks for that
};

// The 2D layer: the program's overlay, then the frame-rate line.
void draw_2d(Canvas& canvas, const DrawList& overlay, const std::string& stats_text) {
  overlay.draw(canvas);
  if (!stats_text.empty()) {
    int scale = std::max(1, canvas.height / 300);
    int w = text_width(stats_text, scale) + 6 * scale, h = stats_band_height(canvas.height);
    fill_rect(canvas, 0, 0, w, h, {0, 0, 0, 150});
    draw_text(canvas, 3 * scale, 3 * scale + scale, stats_text, {255, 255, 120, 255}, scale);
  }
}

// Takes the frame's size and options (the thread count stays the renderer's own).
void prepare(Renderer& renderer, const RenderJob& job) {
  if (renderer.width() != job.width || renderer.height() != job.height) renderer.resize(job.width, job.height);
  int threads = renderer.options.threads;
  renderer.options = job.frame.options;
  renderer.options.threads = threads;
}

Rendered render_job(Renderer& renderer, RenderJob job) {
  auto start = Clock::now();
  Rendered out;
  out.image = Image(job.width, job.height, 0xff000000u);
  FrameDescription& f = job.frame;
  prepare(renderer, job);
  if (f.draw_scene) {
    renderer.render(f.scene);
    renderer.read_color(out.image.pixels.data(), size_t(job.width) * 4, 4);
  } else {
    Vec3 bg = f.scene.background;
    auto c = [](float v) { return uint32_t(std::lrint(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    out.image = Image(job.width, job.height, 0xff000000u | c(bg.z) << 16 | c(bg.y) << 8 | c(bg.x));
  }
  if (!f.screenshot.empty() && !f.screenshot_overlay) out.clean = out.image;
  Canvas canvas{out.image.pixels.data(), job.width, job.height, size_t(job.width) * 4};
  draw_2d(canvas, f.overlay, job.stats_text);
  out.screenshot = std::move(f.screenshot);
  out.ms = ms_since(start);
  return out;
}

// The windowed GPU path: the frame stays on the GPU and the 2D layer is drawn apart,
// into `layer` (premultiplied: Canvas::layer), for Renderer::present_window to blend
// over it. Colour is read back only for a recording or a screenshot (`read_back`).
// `layer_used` says whether the layer has anything in it.
Rendered render_windowed(Renderer& renderer, RenderJob job, bool read_back, Image& layer, bool& layer_used) {
  auto start = Clock::now();
  Rendered out;
  FrameDescription& f = job.frame;
  prepare(renderer, job);
  if (f.draw_scene) {
    renderer.render(f.scene);
  } else {  // the background alone: a frame with nothing drawn
    renderer.begin_frame(f.scene.camera, {}, f.scene.background);
    renderer.end_frame();
  }
  if (read_back) {
    out.image = Image(job.width, job.height, 0xff000000u);
    renderer.read_color(out.image.pixels.data(), size_t(job.width) * 4, 4);
    if (!f.screenshot.empty() && !f.screenshot_overlay) out.clean = out.image;
    Canvas canvas{out.image.pixels.data(), job.width, job.height, size_t(job.width) * 4};
    draw_2d(canvas, f.overlay, job.stats_text);
  }
  layer_used = !f.overlay.ops().empty() || !job.stats_text.empty();
  if (layer_used) {
    if (layer.width != job.width || layer.height != job.height) layer = Image(job.width, job.height, 0);
    else std::fill(layer.pixels.begin(), layer.pixels.end(), uint8_t(0));
    Canvas canvas{layer.pixels.data(), job.width, job.height, size_t(job.width) * 4, true};
    draw_2d(canvas, f.overlay, job.stats_text);
  }
  out.screenshot = std::move(f.screenshot);
  out.ms = ms_since(start);
  return out;
}

}  // namespace

void install_stop_signals() {
  g_stop_signal.store(0);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
}

int stop_signal() { return g_stop_signal.load(); }

int stats_band_height(int frame_height) {
  int scale = std::max(1, frame_height / 300);
  return text_height("0", scale) + 6 * scale;
}

double percentile(std::vector<double> samples, double fraction) {
  if (samples.empty()) return 0;
  std::sort(samples.begin(), samples.end());
  size_t rank = size_t(std::ceil(std::clamp(fraction, 0.0, 1.0) * double(samples.size())));
  return samples[std::clamp<size_t>(rank, 1, samples.size()) - 1];
}

std::string summarize(const LoopResult& r) {
  double med = percentile(r.frame_ms, 0.5), p99 = percentile(r.frame_ms, 0.99);
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "frames=%ld size=%dx%d median_ms=%.2f p99_ms=%.2f fps=%.1f render_median_ms=%.2f render_p99_ms=%.2f",
                r.frames, r.width, r.height, med, p99, med > 0 ? 1000.0 / med : 0.0, percentile(r.render_ms, 0.5),
                percentile(r.render_ms, 0.99));
  return buf;
}

LoopResult run_loop(Program& program, Presenter* presenter, const LoopOptions& o) {
  if (!o.record_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.record_dir, ec);
    if (ec) throw Error("--record: cannot create folder " + o.record_dir + ": " + ec.message());
  }
  const bool fixed = o.fixed_step || o.script || !o.record_dir.empty();
  std::optional<ScriptPlayer> script;
  if (o.script) script.emplace(*o.script);

  int width = o.width, height = o.height;
  bool follow = o.follow_window && presenter;
  if (follow) std::tie(width, height) = presenter->window_size();
  program.resize(width, height);
  bool overlay = o.overlay;
  int mode = -1;  // index into kScreenModes once F2 is pressed; 4 = the window's size
  int asked_mode = -1;  // the last mode the program asked for

  // The renderer, in the window's GL context when the presenter has one and the GPU
  // draws (docs/gpu.md, "In a window"); otherwise offscreen, its frames read back.
  LoopResult result;
  GlContextProvider* gl = presenter && o.backend != BackendChoice::Cpu ? presenter->gl_context() : nullptr;
  std::optional<Renderer> made;
  if (gl) {
    try {
      made.emplace(std::max(width, 1), std::max(height, 1), *gl, o.backend == BackendChoice::Auto);
    } catch (const Error& e) {
      presenter->drop_gl_context(e.what());
      gl = nullptr;
    }
  }
  if (presenter && !gl && presenter->gl_context()) presenter->drop_gl_context("the CPU backend draws");
  // Offscreen, the renderer is made (and later destroyed) on a thread of its own, as
  // its frames are drawn on the render thread: an EGL context cannot be bound on a
  // thread where SDL's renderer holds a GLX context (libglvnd: EGL_BAD_ACCESS).
  if (!made) made.emplace(std::async(std::launch::async, [&] {
                      return Renderer(std::max(width, 1), std::max(height, 1), o.backend);
                    }).get());
  Renderer& renderer = *made;
  const bool windowed = gl != nullptr;
  if (windowed) {
    result.present_path = "gpu, windowed (SDL GL context)";
  } else if (std::string(renderer.stats().backend) == "gpu") {
    const std::string why = !presenter ? "no window" : presenter->gl_missing();
    result.present_path = "gpu, offscreen EGL + read-back" + (why.empty() ? std::string() : " (" + why + ")");
  } else {
    result.present_path = "cpu";
  }
  renderer.options.threads = o.threads;
  if (o.backend != BackendChoice::Cpu && !o.quiet) {
    std::printf("backend=%s (%s)\npresent=%s\n", renderer.stats().backend, renderer.stats().backend_reason,
                result.present_path.c_str());
    std::fflush(stdout);
  }
  InputState input;
  std::vector<InputEvent> events;
  std::future<Rendered> pending;
  long recorded = 0;
  double sim_time = 0;
  auto start = Clock::now();
  auto last = start;
  std::string title;
  Image last_image;  // what the window shows, for lingering
  Image layer;       // windowed: the last frame's 2D layer
  bool layer_used = false;

  // Windowed: the last frame (still in the GPU's framebuffer) and its 2D layer into the
  // window's back buffer, then shown.
  auto present_windowed = [&] {
    auto [ww, wh] = presenter->window_size();
    renderer.present_window(ww, wh, layer_used ? layer.pixels.data() : nullptr);
    presenter->take_exposed();
    presenter->swap();
  };

  // Shows (and records) a finished frame; a windowed one is already in the window.
  auto show = [&](Rendered r) {
    result.render_ms.push_back(r.ms);
    if (presenter && !windowed) presenter->present(r.image.pixels.data(), r.image.width, r.image.height);
    if (!o.record_dir.empty()) {
      char name[64];
      std::snprintf(name, sizeof name, "/frame_%05ld.png", recorded);
      write_png_whole(o.record_dir + name, r.image);
    }
    ++recorded;
    if (!r.screenshot.empty()) {
      write_png_whole(r.screenshot, r.clean.width > 0 ? r.clean : r.image);
      std::printf("wrote %s (%dx%d)\n", r.screenshot.c_str(), r.image.width, r.image.height);
      std::fflush(stdout);
    }
    last_image = std::move(r.image);
  };

  // In a window with nothing bounding the run, a frame in which nothing changed (no input,
  // and the program says so) is not drawn: an idle viewer costs no CPU.
  const bool may_idle = presenter && !fixed && o.frames <= 0;
  bool drew_last = false;
  bool quit = false;
  for (long n = 0; !quit && (o.frames <= 0 || n < o.frames); ++n) {
    // Time step.
    auto now = Clock::now();
    double dt = fixed ? kFixedStep : std::clamp(std::chrono::duration<double>(now - last).count(), 0.0, 0.1);
    if (n > 0 && drew_last) result.frame_ms.push_back(std::chrono::duration<double, std::milli>(now - last).count());
    last = now;
    sim_time += n > 0 ? dt : 0.0;

    // Events: the window's, then the script's due ones.
    events.clear();
    if (presenter) presenter->poll(events);
    if (script) script->due(sim_time, events);
    auto set_mode = [&](int m) {
      mode = m;
      follow = mode == 4 && presenter;
      if (mode < 4) width = kScreenModes[mode].width, height = kScreenModes[mode].height;
      else if (presenter) std::tie(width, height) = presenter->window_size();
      program.resize(width, height);
    };
    for (const InputEvent& e : events) {
      if (e.kind == InputEvent::Quit) quit = true;
      if (e.kind == InputEvent::KeyDown && e.key == KeyF11 && presenter) presenter->toggle_fullscreen();
      if (e.kind == InputEvent::KeyDown && e.key == KeyF3) overlay = !overlay;
      if (e.kind == InputEvent::KeyDown && e.key == KeyF2) set_mode((mode + 1) % 5);
      if (e.kind == InputEvent::Resize && follow && e.x > 0 && e.y > 0) {
        width = std::min(e.x, 16384), height = std::min(e.y, 16384);
        program.resize(width, height);
      }
      input.apply(e);
      program.event(e, input);
    }
    // A screen mode chosen on an options screen, as F2 would.
    if (int asked = program.screen_mode(); asked != asked_mode) {
      if (asked >= 0 && asked <= 4) {
        set_mode(asked);
      } else if (asked == -1) {  // back to the size the run started with
        mode = -1;
        follow = o.follow_window && presenter;
        if (follow) std::tie(width, height) = presenter->window_size();
        else width = o.width, height = o.height;
        program.resize(width, height);
      }
    }
    asked_mode = program.screen_mode();
    if (program.finished() || g_stop_signal.load() != 0) quit = true;
    if (quit) break;
    program.set_gamepad(presenter ? presenter->gamepad() : GamepadState{});

    program.update(n > 0 ? dt : 0.0, input);
    if (o.synth) program.sound(*o.synth);
    if (presenter && program.title() != title) presenter->set_title(title = program.title());
    if (may_idle && n > 0 && events.empty() && !program.changed()) {
      if (pending.valid()) show(pending.get());  // the last frame drawn goes up first
      if (windowed && presenter->take_exposed()) present_windowed();
      drew_last = false;
      std::this_thread::sleep_for(std::chrono::milliseconds(8));
      continue;
    }
    drew_last = true;

    RenderJob job;
    program.frame(job.frame);
    job.width = width, job.height = height;
    if (overlay) {
      double med = percentile(std::vector<double>(result.frame_ms.end() - std::min<size_t>(result.frame_ms.size(), 60),
                                                  result.frame_ms.end()),
                              0.5);
      char buf[128];
      std::snprintf(buf, sizeof buf, "%.0f FPS  %.1f MS  RENDER %.1f MS  %dX%d", med > 0 ? 1000.0 / med : 0.0, med,
                    result.render_ms.empty() ? 0.0 : result.render_ms.back(), width, height);
      job.stats_text = buf;
    }

    if (windowed) {
      // The window's GL context is this thread's (SDL made it here): the frame is drawn
      // and presented here, one after the other. The GPU works on its own meanwhile.
      const bool read_back = !o.record_dir.empty() || !job.frame.screenshot.empty();
      auto t = Clock::now();
      Rendered r = render_windowed(renderer, std::move(job), read_back, layer, layer_used);
      present_windowed();
      r.ms = ms_since(t);
      show(std::move(r));
      ++result.frames;
      if (o.end_with_script && script && script->finished()) quit = true;
      if (fixed && o.pace_to_clock) {
        auto due = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(sim_time));
        std::this_thread::sleep_until(due);
      }
      continue;
    }

    // Render frame n on the render thread while frame n - 1 is presented here.
    // (The renderer draws one frame at a time: take frame n - 1 first.)
    std::optional<Rendered> previous;
    if (pending.valid()) previous = pending.get();
    pending = std::async(std::launch::async, render_job, std::ref(renderer), std::move(job));
    if (previous) show(std::move(*previous));
    ++result.frames;
    if (o.end_with_script && script && script->finished()) quit = true;

    // A fixed step with sound on: keep the program's time with the audio's.
    if (fixed && o.pace_to_clock) {
      auto due = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(sim_time));
      std::this_thread::sleep_until(due);
    }
  }
  if (pending.valid()) show(pending.get());
  result.width = width, result.height = height;

  // Keep the last frame on screen a while (tests take the window's picture then).
  if (presenter && o.linger > 0) {
    auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.linger));
    while (Clock::now() < until && g_stop_signal.load() == 0) {
      events.clear();
      presenter->poll(events);
      if (std::any_of(events.begin(), events.end(), [](const InputEvent& e) {
            return e.kind == InputEvent::Quit || (e.kind == InputEvent::KeyDown && e.key == KeyEscape);
          }))
        break;
      if (windowed && presenter->take_exposed()) present_windowed();
      if (!windowed && last_image.width > 0)
        presenter->present(last_image.pixels.data(), last_image.width, last_image.height);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  if (!o.quiet) {
    std::printf("%s\n", summarize(result).c_str());
    std::fflush(stdout);
  }
  if (!windowed) std::async(std::launch::async, [&] { made.reset(); }).get();  // (where it was made)
  return result;
}

}  // namespace velocity::realtime
