// Display lists: glNewList records the compiled entry points as commands (api.cpp),
// glCallList runs them.
#include "context.hpp"

namespace velocity::gl {

GLuint Context::gen_lists(GLsizei range) {
  if (in_begin_error()) return 0;
  if (range < 0) return error(GL_INVALID_VALUE), 0;
  if (range == 0) return 0;
  if (lists_.stored.size() + size_t(range) > (size_t(1) << 20)) return error(GL_OUT_OF_MEMORY), 0;
  // The first run of `range` unused names after the largest one in use.
  const GLuint first = lists_.stored.empty() ? 1 : lists_.stored.rbegin()->first + 1;
  if (first == 0 || uint64_t(first) + uint64_t(range) > 0xffffffffull) return error(GL_OUT_OF_MEMORY), 0;
  for (GLsizei i = 0; i < range; ++i) lists_.stored[first + GLuint(i)];
  return first;
}

void Context::new_list(GLuint list, GLenum mode) {
  if (in_begin_error()) return;
  if (list == 0) return error(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return error(GL_INVALID_ENUM);
  if (lists_.compiling) return error(GL_INVALID_OPERATION);
  lists_.compiling = list;
  lists_.mode = mode;
  lists_.recorded.clear();
  lists_.overflow = false;
}

void Context::end_list() {
  if (in_begin_error()) return;
  if (!lists_.compiling) return error(GL_INVALID_OPERATION);
  if (lists_.overflow) {
    error(GL_OUT_OF_MEMORY);
    lists_.recorded.clear();
  }
  if (lists_.stored.size() < (size_t(1) << 20) || lists_.stored.count(lists_.compiling))
    lists_.stored[lists_.compiling] = std::move(lists_.recorded);
  lists_.recorded = {};
  lists_.compiling = 0;
}

void Context::record(ListCommand cmd) {
  if (lists_.overflow) return;
  if (lists_.recorded.size() >= kMaxListCommands) {
    lists_.overflow = true;
    return;
  }
  lists_.recorded.push_back(std::move(cmd));
}

void Context::record_draw(const std::function<void()>& body) {
  std::vector<ListCommand> outer = std::move(lists_.recorded);
  lists_.recorded = {};
  std::vector<ListCommand> draw;
  try {
    body();
    draw = std::move(lists_.recorded);
  } catch (...) {
    lists_.recorded = std::move(outer);
    throw;
  }
  lists_.recorded = std::move(outer);
  if (lists_.overflow || lists_.recorded.size() + draw.size() >= kMaxListCommands) {
    lists_.overflow = true;
    return;
  }
  record([draw = std::move(draw)](Context& c) {
    if (c.in_begin_error()) return;
    for (const ListCommand& k : draw) {  // each counts against the outermost call's budget
      if (c.lists_.budget == 0) break;
      if (--c.lists_.budget == 0) c.error(GL_OUT_OF_MEMORY);
      k(c);
    }
  });
}

void Context::call_list(GLuint list) {
  if (lists_.depth >= kMaxListNesting) return;  // GL: deeper calls are ignored
  auto it = lists_.stored.find(list);
  if (it == lists_.stored.end()) return;
  if (lists_.depth == 0) lists_.budget = kMaxListCallCommands;
  ++lists_.depth;
  // The commands of a list cannot change lists (glNewList, glDeleteLists are never
  // compiled), so the vector stays put while it runs.
  for (const ListCommand& c : it->second) {
    if (lists_.budget == 0) break;
    if (--lists_.budget == 0) error(GL_OUT_OF_MEMORY);
    c(*this);
  }
  --lists_.depth;
}

void Context::delete_lists(GLuint list, GLsizei range) {
  if (in_begin_error()) return;
  if (range < 0) return error(GL_INVALID_VALUE);
  if (lists_.depth > 0) return;
  for (GLsizei i = 0; i < range; ++i) {
    const uint64_t id = uint64_t(list) + uint64_t(i);
    if (id > 0xffffffffull) break;
    lists_.stored.erase(GLuint(id));
  }
}

}  // namespace velocity::gl
