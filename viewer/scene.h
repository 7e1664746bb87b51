// What every lab's scene is made of (viewer/scenes/NN_name.cpp), and the few helpers
// they share (shapes to draw are in viewer/shapes.h). A scene has three parts, in this
// order in its file (the drawing may stand apart, in NN_name.draw.cpp):
//   setup   its constructor: default inputs, a preset's, or a replay token's (the
//           token's query picks the scene's mode);
//   update  runs the student's functions step by step (a stub shows "not implemented
//           yet"), the exact oracle, and the lab's judges, and fills `steps`;
//   draw    the 3D picture, student beside exact, coloured by verdict; and inputs(),
//           the scene's inputs as editable values in the panel.
#pragma once

#include "viewer/handles.h"
#include "viewer/render.h"

#include "common/harness/check.h"
#include "common/harness/codec.h"
#include "common/not_implemented.h"

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace viewer {

enum class Verdict { agree, disagree, ambiguous, stub, none };

inline Color colour(Verdict v) {
  switch (v) {
    case Verdict::agree: return palette::agree;
    case Verdict::disagree: return palette::disagree;
    case Verdict::ambiguous: return palette::ambiguous;
    case Verdict::stub: return palette::stub;
    case Verdict::none: break;
  }
  return palette::muted;
}

inline const char* word(Verdict v) {
  switch (v) {
    case Verdict::agree: return "agrees";
    case Verdict::disagree: return "disagrees";
    case Verdict::ambiguous: return "ambiguous: any answer passes";
    case Verdict::stub: return "not implemented yet";
    case Verdict::none: break;
  }
  return "";
}

// One line of a step in the panel: a quantity, the student's value, the exact value.
struct Row {
  std::string quantity, yours, exact;
};

// One step of the lab, as the panel shows it and `--screenshot` prints it.
struct Step {
  std::string tag;    // "L02S1", as in the handout and the student's file
  std::string title;  // "segment_plane: d_a, d_b, the crossing point"
  Verdict verdict = Verdict::none;
  std::vector<Row> rows;
  std::string note;  // why it disagrees, the stub's message, or why the step has nothing to show
};

// The student's answer to one call, or why there is none.
template <class T> struct Attempt {
  std::optional<T> value;
  bool stub = false;    // NotImplemented: "not implemented yet (L02S1)"
  std::string problem;  // the stub's message, or the exception's
  explicit operator bool() const { return value.has_value(); }
  const T& operator*() const { return *value; }
  const T* operator->() const { return &*value; }
};

template <class F> auto attempt(F&& call) {
  Attempt<decltype(call())> a;
  try {
    a.value = call();
  } catch (const labkit::NotImplemented& e) {
    a.stub = true;
    a.problem = e.what();
  } catch (const std::exception& e) {
    a.problem = std::string("your code threw an exception: ") + e.what();
  }
  return a;
}

// A step for an attempt: the judge's verdict when there is an answer, otherwise "not
// implemented yet" or the exception. `judge` is called only when there is an answer.
template <class T, class Judge> Step judged(std::string tag, std::string title, const Attempt<T>& a, Judge&& judge) {
  Step s{std::move(tag), std::move(title), Verdict::none, {}, {}};
  if (!a) {
    s.verdict = a.stub ? Verdict::stub : Verdict::disagree;
    s.note = a.problem;
    const std::size_t open = a.problem.find('('), close = a.problem.find(')');
    if (a.stub && open != std::string::npos && close > open)
      s.note = "write the step marked " + a.problem.substr(open + 1, close - open - 1) + " in your file";
    return s;
  }
  const labkit::check::Outcome o = judge(*a);
  using V = labkit::check::Outcome::Verdict;
  s.verdict =
      o.verdict == V::pass ? Verdict::agree : (o.verdict == V::ambiguous ? Verdict::ambiguous : Verdict::disagree);
  if (s.verdict == Verdict::disagree) s.note = o.why.empty() ? "expected " + o.expected + ", got " + o.got : o.why;
  return s;
}

// Two verdicts of one step joined: the worse one shows.
inline Verdict worse(Verdict a, Verdict b) {
  const auto rank = [](Verdict v) {
    return v == Verdict::disagree    ? 4
           : v == Verdict::stub      ? 3
           : v == Verdict::ambiguous ? 2
           : v == Verdict::agree     ? 1
                                     : 0;
  };
  return rank(a) >= rank(b) ? a : b;
}

// A second answer judged within the same step (test_ beside find_, any_hit beside
// first_hit): the worse verdict shows, and the first note.
void join(Step& step, const Step& other);
template <class T, class Judge> void join(Step& step, const Attempt<T>& a, Judge&& judge) {
  join(step, judged("", "", a, std::forward<Judge>(judge)));
}

// What draw() is given each frame.
struct Frame {
  Renderer& render;
  bool show_exact = true;  // the toggle (key E): draw the exact answer beside the student's
  bool figure = false;     // a handout figure: the same picture, fewer words
  int focus = 0;           // draw only this step's quantities (0: every step)
  bool shows(int step) const { return focus == 0 || focus == step; }
};

// A named input a scene offers in its "examples" list; the handouts' figures are some
// of them. `token` is a replay token, or null for a preset the scene builds in code.
struct Preset {
  const char* name;
  const char* description;
  const char* token;
  bool figure = false;
  float yaw = -60, pitch = 28;  // the camera, in degrees
  int focus = 0;                // the step the picture is about (0: all)
};

struct Setup {
  std::string token;   // a replay token ("query:v1,v2,..."), or empty
  std::string preset;  // a preset's name, or empty
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual void update() = 0;
  virtual void draw(Frame& frame) = 0;
  virtual bool inputs() = 0;  // the panel's editable values; true when one changed
  virtual std::vector<Handle> handles() = 0;
  virtual std::string token() const = 0;  // the input now, as `./labkit check --case` takes it

  std::string mode;                            // which of the scene's inputs it shows: "segment and triangle"
  std::vector<Step> steps;                     // filled by update()
  labkit::Vec3 center = labkit::Vec3::Zero();  // what the camera frames at first
  double radius = 1;
  float yaw = -60, pitch = 28;
  int focus = 0;

 protected:
  // The preset named in `setup` (or null), its camera and focus taken.
  const Preset* view_preset(const std::vector<Preset>& presets, const Setup& setup);
  // The camera frames `box`: its centre, and `share` of its diagonal as the radius.
  void frame(const Eigen::AlignedBox3d& box, double share = 0.5);
  // The ground grid, spaced to the framed radius, and the axes: every draw() starts so.
  void draw_ground(Renderer& r) const;
};

// Helpers for the panel and for scenes' text.
bool edit(const char* label, labkit::Vec3& v, float speed = 0.05f);
bool edit(const char* label, double& x, float speed = 0.05f, double low = 0, double high = 0);
std::string num(double x);  // 4 significant digits, for the screen
std::string num(const labkit::Vec3& v);
// A yes/no answer in the panel, in the step's own words ("hit" / "miss").
inline std::string yes_no(bool b, const char* yes = "yes", const char* no = "no") { return b ? yes : no; }
const Preset* find_preset(const std::vector<Preset>& presets, const std::string& name);
// The token a scene starts from: the replay token, a preset's, or `fallback`.
std::string starting_token(const Setup& setup, const std::vector<Preset>& presets, const std::string& fallback);
// A replay token whose query belongs to no mode of the scene (another lab's, perhaps).
struct UnknownQuery : labkit::BadToken {
  using labkit::BadToken::BadToken;
};
// `listed`: the query is the lab's, but the scene has no view of it.
UnknownQuery unknown_query(const std::string& lab, const std::string& query, const std::string& shown,
                           bool listed = false);

// Loaders, one per input type: `Loaders{[&](auto q, const TreeQuery& in) {...}, ...}`.
template <class... F> struct Loaders : F... { using F::operator()...; };
template <class... F> Loaders(F...) -> Loaders<F...>;

// A replay token's input, read as the type its query takes in the lab's table
// (tests/NN_name/queries.h) and handed to the loader that takes that type. The scene
// shows exactly the queries whose input one of its loaders takes: any other, of this lab
// or another, is an UnknownQuery that lists those.
template <class Load, class... Inputs>
void load_token(const std::string& lab, const labkit::check::QueryTable<Inputs...>& table,
                const labkit::ParsedToken& token, Load&& load) {
  std::string shown;
  bool loaded = false, listed = false;
  const auto one = [&](const auto& q) {
    using Input = typename std::decay_t<decltype(q)>::InputType;
    listed = listed || token.query == q.name;
    if constexpr (std::is_invocable_v<Load&, decltype(q), const Input&>) {
      shown += (shown.empty() ? "" : ", ") + std::string(q.name);
      if (!loaded && token.query == q.name) load(q, labkit::input_from_token<Input>(token)), loaded = true;
    }
  };
  std::apply([&](const auto&... q) { (one(q), ...); }, table.queries);
  if (!loaded) throw unknown_query(lab, token.query, shown, listed);
}

}  // namespace viewer
