// The sound: a synthesiser that the audio device pulls samples from (mono, signed
// 16-bit). An engine note whose pitch the program sets, a few effects, and a tune for
// the title screen, all generated: no sound files. Thread-safe: the program sets
// parameters on its thread (one thread) while the audio callback renders on the audio
// thread; setting never waits for the audio thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace velocity::realtime {

enum class Effect { Click, Crash, Whoosh };

class Synth {
 public:
  explicit Synth(int sample_rate = 44100);

  // The engine: a note with a strong fundamental at `hz` (a few harmonics on top) at
  // `volume` 0..1; the pitch glides to a new value over about 50 ms.
  void set_engine(bool on, float hz, float volume = 0.5f);
  void set_music(bool on);
  // Everything together, 0 (silent) .. 1 (as made); the options screen's volume.
  void set_volume(float volume);
  void play(Effect effect);

  // Renders `count` samples into `out` (the audio thread).
  void render(int16_t* out, size_t count);
  int sample_rate() const { return rate_; }
  // The engine's current (glided) frequency, for tests.
  float engine_hz() const;

 private:
  struct Voice {
    Effect effect;
    size_t age = 0;
  };
  float next_sample();
  float music_sample();
  void hand_over();

  // What the program asked for (its thread only), handed to the fields below when the
  // audio thread is not using them.
  struct Wanted {
    float volume = 1.0f, engine_target = 60, engine_volume = 0;
    bool engine_on = false, music_on = false;
    std::vector<Effect> effects;
  } wanted_;

  mutable std::mutex mutex_;
  int rate_;
  float volume_ = 1.0f;
  // Engine.
  bool engine_on_ = false;
  float engine_target_ = 60, engine_hz_ = 60, engine_volume_ = 0, engine_level_ = 0;
  double engine_phase_ = 0;
  // Music.
  bool music_on_ = false;
  float music_level_ = 0;
  size_t music_pos_ = 0;
  double lead_phase_ = 0, bass_phase_ = 0;
  // Effects.
  std::vector<Voice> voices_;
  uint32_t noise_ = 0x12345678u;
};

}  // namespace velocity::realtime
