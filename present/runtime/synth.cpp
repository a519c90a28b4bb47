#include "runtime/synth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace velocity::realtime {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The title tune: A minor arpeggios, eighth notes at 140 beats a minute, as MIDI note
// numbers (0: rest); the bass plays the chord's root an octave down.
constexpr int kMelody[] = {69, 72, 76, 72, 69, 72, 76, 79, 65, 69, 72, 69, 65, 69, 72, 77,
                           67, 71, 74, 71, 67, 71, 74, 79, 64, 68, 71, 68, 64, 68, 71, 76};
constexpr int kBass[] = {45, 41, 43, 40};  // one chord per 8 notes

double midi_hz(int note) { return 440.0 * std::pow(2.0, (note - 69) / 12.0); }

}  // namespace

Synth::Synth(int sample_rate) : rate_(std::max(sample_rate, 8000)) {}

// The setters change the program's copy and hand it over when the audio thread is not
// rendering. They never wait for it: on a busy machine the audio thread can be taken off
// the processor while it holds the lock, and a frame that waited for it would wait for
// the scheduler (tens of milliseconds). What is not handed over now goes with the next
// call (the programs set their sound every frame).
void Synth::set_volume(float volume) {
  if (std::isfinite(volume)) wanted_.volume = std::clamp(volume, 0.0f, 1.0f);
  hand_over();
}

void Synth::set_engine(bool on, float hz, float volume) {
  wanted_.engine_on = on;
  if (std::isfinite(hz)) wanted_.engine_target = std::clamp(hz, 20.0f, 2000.0f);
  if (std::isfinite(volume)) wanted_.engine_volume = std::clamp(volume, 0.0f, 1.0f);
  hand_over();
}

void Synth::set_music(bool on) {
  wanted_.music_on = on;
  hand_over();
}

void Synth::play(Effect effect) {
  if (wanted_.effects.size() < 16) wanted_.effects.push_back(effect);
  hand_over();
}

void Synth::hand_over() {
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock) return;
  volume_ = wanted_.volume;
  engine_on_ = wanted_.engine_on;
  engine_target_ = wanted_.engine_target;
  engine_volume_ = wanted_.engine_volume;
  music_on_ = wanted_.music_on;
  for (Effect e : wanted_.effects)
    if (voices_.size() < 16) voices_.push_back({e, 0});
  wanted_.effects.clear();
}

float Synth::engine_hz() const {
  std::lock_guard lock(mutex_);
  return engine_hz_;
}

float Synth::music_sample() {
  const size_t note_len = size_t(rate_ * 60 / 140 / 2);  // an eighth note
  const size_t n = std::size(kMelody);
  size_t idx = (music_pos_ / note_len) % n;
  size_t in_note = music_pos_ % note_len;
  ++music_pos_;
  lead_phase_ += midi_hz(kMelody[idx]) / rate_;
  bass_phase_ += midi_hz(kBass[(idx / 8) % std::size(kBass)] - 12) / rate_;
  lead_phase_ -= std::floor(lead_phase_);
  bass_phase_ -= std::floor(bass_phase_);
  // Lead: a square wave with a plucked envelope; bass: a triangle.
  float env = std::exp(-float(in_note) / float(rate_) * 6.0f);
  float lead = (lead_phase_ < 0.5 ? 1.0f : -1.0f) * env * 0.18f;
  float bass = float(4.0 * std::abs(bass_phase_ - 0.5) - 1.0) * 0.22f;
  return lead + bass;
}

float Synth::next_sample() {
  float s = 0;
  // Engine: glide the pitch (one-pole, ~50 ms) and the level (~20 ms).
  const float glide = 1.0f - std::exp(-1.0f / (0.05f * float(rate_)));
  const float fade = 1.0f - std::exp(-1.0f / (0.02f * float(rate_)));
  engine_hz_ += (engine_target_ - engine_hz_) * glide;
  engine_level_ += ((engine_on_ ? engine_volume_ : 0.0f) - engine_level_) * fade;
  if (engine_level_ > 1e-4f) {
    engine_phase_ += double(engine_hz_) / rate_;
    engine_phase_ -= std::floor(engine_phase_);
    double p = kTwoPi * engine_phase_;
    // The fundamental dominates (so the note's pitch is its frequency); harmonics give
    // it body.
    s += engine_level_ * float(0.6 * std::sin(p) + 0.22 * std::sin(2 * p) + 0.1 * std::sin(3 * p));
  }
  // Music fades in and out.
  music_level_ += ((music_on_ ? 1.0f : 0.0f) - music_level_) * fade;
  if (music_level_ > 1e-4f) s += music_level_ * music_sample();
  // Effects.
  for (Voice& v : voices_) {
    float t = float(v.age) / float(rate_);
    ++v.age;
    noise_ = noise_ * 1664525u + 1013904223u;
    float noise = float(int32_t(noise_)) / 2147483648.0f;
    switch (v.effect) {
      case Effect::Click: s += 0.5f * std::exp(-t * 60.0f) * float(std::sin(kTwoPi * 1200.0 * t)); break;
      case Effect::Crash: s += 0.7f * std::exp(-t * 8.0f) * noise; break;
      case Effect::Whoosh: s += 0.3f * std::sin(float(std::numbers::pi) * std::min(t / 0.4f, 1.0f)) * noise; break;
    }
  }
  std::erase_if(voices_, [this](const Voice& v) { return v.age > size_t(rate_) / 2; });
  return s;
}

void Synth::render(int16_t* out, size_t count) {
  std::lock_guard lock(mutex_);
  for (size_t i = 0; i < count; ++i) {
    float s = std::clamp(next_sample() * volume_, -1.0f, 1.0f);
    out[i] = int16_t(std::lrint(s * 32000.0f));
  }
}

}  // namespace velocity::realtime
