// A lab's queries: the names its tests give the questions they ask (a replay token's
// prefix, "first_hit:0.5,...") and the input each takes. Each lab lists them once, at the
// end of tests/NN_name/queries.h, as a table the tests, the viewer's scene and its
// presets read:
//
//   #define LABKIT_LAB06_QUERIES(X, X_IN) X(first_hit, TreeQuery) X_IN(robust, classify, PointQuery) ...
//   namespace labkit::lab06::query { LABKIT_QUERIES(LABKIT_LAB06_QUERIES) }
//
// which declares query::first_hit (a Query<TreeQuery> named "first_hit"),
// query::robust_classify (a Query<PointQuery> named "robust.classify") and query::table.
#pragma once

#include "common/harness/codec.h"

#include <string>
#include <string_view>
#include <tuple>
#include <utility>

namespace labkit::check {

template <class Input> struct Query {
  using InputType = Input;
  const char* name;
};

template <class Input> bool operator==(const Query<Input>& q, const std::string& name) { return name == q.name; }
template <class A, class B> bool operator==(const Query<A>& a, const Query<B>& b) {
  return std::string_view(a.name) == b.name;
}

template <class... Inputs> struct QueryTable {
  std::tuple<Query<Inputs>...> queries;

  // "build_kd_tree, first_hit, ...": for an error that lists what a token may start with.
  std::string names() const {
    std::string all;
    std::apply([&](const auto&... q) { ((all += (all.empty() ? "" : ", ") + std::string(q.name)), ...); }, queries);
    return all;
  }

  // Calls visit(query, input) with the token's numbers read as the input its query takes;
  // false when the table has no query of that name. A malformed token throws BadToken.
  template <class Visit> bool visit(const ParsedToken& token, Visit&& fn) const {
    bool found = false;
    std::apply([&](const auto&... q) { ((found = found || visit_if(token, q, fn)), ...); }, queries);
    return found;
  }

 private:
  template <class Input, class Visit> static bool visit_if(const ParsedToken& token, const Query<Input>& q, Visit& fn) {
    if (token.query != q.name) return false;
    fn(q, input_from_token<Input>(token));
    return true;
  }
};
template <class... Inputs> QueryTable(std::tuple<Query<Inputs>...>) -> QueryTable<Inputs...>;

}  // namespace labkit::check

namespace labkit {

// "first_hit:0.5,...": the token that replays `input` as the query `q` (codec.h's, typed).
template <class Input>
std::string replay_token(const check::Query<Input>& q, const typename check::Query<Input>::InputType& input) {
  return replay_token(std::string(q.name), input);
}

}  // namespace labkit

// The declarations a lab's table expands to (see the top of this file).
#define LABKIT_QUERY(name, Input) inline constexpr ::labkit::check::Query<Input> name{#name};
#define LABKIT_QUERY_IN(group, name, Input) \
  inline constexpr ::labkit::check::Query<Input> group##_##name{#group "." #name};
#define LABKIT_QUERY_ENTRY(name, Input) name,
#define LABKIT_QUERY_ENTRY_IN(group, name, Input) group##_##name,
#define LABKIT_QUERIES(TABLE)          \
  TABLE(LABKIT_QUERY, LABKIT_QUERY_IN) \
  inline const ::labkit::check::QueryTable table{std::tuple{TABLE(LABKIT_QUERY_ENTRY, LABKIT_QUERY_ENTRY_IN)}};
