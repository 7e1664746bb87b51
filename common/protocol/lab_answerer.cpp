// main() of one lab's answerer: the process that runs the code under test and nothing
// else of the kit's but the geometry types (answerer.h). Linked with the student's
// objects, the reference or a mutant; compiled once per lab like lab_calls.cpp.
// A lab's queries.h helpers that run in the answerer (a batch of queries on one big input)
// are defined here only.
#define LABKIT_IN_ANSWERER
#include LABKIT_LAB_QUERIES

#include "common/protocol/calls.h"

#include <cstring>

int main(int argc, char** argv) {
  using namespace labkit;
  using namespace labkit::LABKIT_LAB_NAMESPACE;
  if (argc == 2 && std::strcmp(argv[1], "--probe") == 0) {  // has the lab been begun? (calls.h)
    remote::Probes probes;
    LABKIT_LAB_CALLS(LABKIT_PROBE_CALL, LABKIT_PROBE_METHOD)
    return remote::probe(probes);
  }
  remote::Table table;
  LABKIT_LAB_CALLS(LABKIT_TABLE_CALL, LABKIT_TABLE_METHOD)
#ifdef LABKIT_LAB_SERVED  // queries.h's: this lab's given functions are counted
  return remote::serve(table, true);
#else
  return remote::serve(table, false);
#endif
}
