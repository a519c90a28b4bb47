// How a C entry point reaches the current context (api.cpp, api_pixels.cpp): now(f)
// runs f on it at once; compiled(f) records f into the display list being compiled
// (and runs it too with GL_COMPILE_AND_EXECUTE) or runs it. No C++ exception leaves
// either: out of memory is GL_OUT_OF_MEMORY.
#pragma once

#include <exception>

#include "context.hpp"

namespace velocity::gl::entry {

template <class F>
void now(F&& f) {
  Context* c = current();
  if (!c) return;
  try {
    f(*c);
  } catch (const std::exception&) {
    c->error(GL_OUT_OF_MEMORY);
  }
}

template <class F>
void compiled(F&& f) {
  Context* c = current();
  if (!c) return;
  try {
    if (c->compiling()) {
      c->record(ListCommand(f));
      if (!c->compile_and_execute()) return;
    }
    f(*c);
  } catch (const std::exception&) {
    c->error(GL_OUT_OF_MEMORY);
  }
}

}  // namespace velocity::gl::entry

#define NOW(...) velocity::gl::entry::now([&](velocity::gl::Context& c) { __VA_ARGS__; })
#define LIST(...) velocity::gl::entry::compiled([=](velocity::gl::Context& c) { __VA_ARGS__; })
