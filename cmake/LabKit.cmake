# labkit_add_labs(): every lab grading/manifest.json lists, through
# labkit_add_lab(NN name): everything one lab needs, from its files alone.
#
# The code under test never shares a process with the judge (common/protocol/answerer.h):
#
#   labs/NN_name/*.cpp            -> labNN_student     (the student's file: one small object)
#   solutions/NN_name/*.cpp       -> labNN_reference   (absent in a student release); its
#                                    `// mutant` lines -> labNN_mutant_X, the reference with
#                                    one classic mistake each (cmake/Mutants.cmake)
#   answer_NN_name_X              -> the answerer: the lab's functions from labNN_X (student,
#                                    reference or a mutant) behind common/protocol/lab_answerer.cpp;
#                                    nothing of the kit's but the geometry types. A student's
#                                    edit recompiles one file and relinks this small program.
#   tests/NN_name/               the lab's checker, in one folder:
#     queries.h                   -> the lab's functions and types on the wire, each query's
#                                    input, the lab's table of queries, and the generators'
#                                    and the verdicts' declarations (both processes)
#     judge.h (if any)            -> helpers the generators, judges, tests and scene share
#     generators*.cpp             -> labNN_generators  (random inputs: the tests' and the
#                                    benchmarks', not the viewer's)
#     judge*.cpp                  -> labNN_judge       (verdicts against the oracle; the viewer shares
#                                    it; judge_internal.h: what the judge's own files share)
#     test.cpp                    -> test_NN_name      (examples and random cases: the judge's
#                                    process, linked once; it runs the answerer named by
#                                    LABKIT_ANSWERER and calls the lab's functions there)
#     given*.cpp (if any)         -> given_NN_name     (ready tools the lab's header declares,
#                                    linked with every implementation)
#   grading record                -> build/grading/NN_name.{json,link}: how ./labkit grade
#                                    links a submission's answerer (see runner/lab_build.h)
#   viewer/scenes/NN_name.cpp     -> the lab's viewer scene, compiled into both viewers
#                                    (viewer/CMakeLists.txt; its line in viewer/scenes/scenes.h)
#
# ctest runs each step of the reference as its own test, "labNN.stepK", with the steps
# read from grading/manifest.json.
file(READ "${PROJECT_SOURCE_DIR}/grading/manifest.json" LABKIT_MANIFEST)

# labkit_kit_code(target [-O0|-O1|-Og]): the kit's own code (oracle, judges, harness,
# runner) is built without debug information in the default RelWithDebInfo build. Students
# debug their own files, which keep -g; on the template-heavy judges and generators -g
# costs a third of the first build, the one a new student waits for. An optimisation level
# given replaces -O2 for code whose speed barely shows: Catch2's runner at -O0; the
# runner, the harness and the report at -O1; the test programs at -Og, not -O0: an inline
# function that both a test program and its judge use (Eigen's, the lab header's) is
# linked once, from the test program, which comes first on the link line, so the judges'
# calls to it ran at the test program's level (at -O0, lab 04's step 4 took 1.28 s
# against 0.37 s at -Og).
function(labkit_kit_code target)
  if(CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo")
    target_compile_options(${target} PRIVATE -g0 ${ARGN})
  endif()
endfunction()

# labkit_student_code(target): a student's file, recompiled at every save, at -Og: g++
# compiles an Eigen-heavy file in about half the time -O2 takes (lab 02's finished file:
# 2.9 s against 4.8 s) and the answers run as fast (the references' steps: 21.5 CPU-seconds
# against 21.1), and a debugger follows the code line by line. Line tables (-g1) are
# enough for a crash's backtrace with file and line (`./labkit check --debug`) and save
# about a second per save; for a debugger that shows local variables, configure with
# -DLABKIT_FULL_DEBUG_INFO=ON (only the students' files are rebuilt). g++ starts
# collecting its own garbage at a 128 MB heap: letting it grow to 256 MB first (20 MB more
# at the peak) saves 0.3 s of each save's compile in labs 02 and 07. ./labkit grade compiles
# a submission with this same command (runner/lab_build.h).
option(LABKIT_FULL_DEBUG_INFO "Full debug information (-g) for the students' files" OFF)
function(labkit_student_code target)
  if(CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo")
    target_compile_options(${target} PRIVATE -Og)
    if(NOT LABKIT_FULL_DEBUG_INFO)
      target_compile_options(${target} PRIVATE -g1)
    endif()
  endif()
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE "SHELL:--param ggc-min-heapsize=262144")
  endif()
endfunction()

# labkit_implementation(target stem [STUDENT] sources...): one implementation of lab
# `stem`'s functions (the student's file, the reference, or a mutant) as a library: the
# lab's header folder, the geometry types and the given functions, and the precompiled
# geometry header built with the same flags (a student's, or the kit's).
function(labkit_implementation target stem)
  cmake_parse_arguments(PARSE_ARGV 2 I "STUDENT" "" "")
  add_library(${target} STATIC ${I_UNPARSED_ARGUMENTS})
  target_include_directories(${target} PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
  target_link_libraries(${target} PUBLIC labkit_geometry labkit_given)
  if(TARGET given_${stem})
    target_link_libraries(${target} PUBLIC given_${stem})
  endif()
  if(I_STUDENT)
    labkit_student_code(${target})
    target_precompile_headers(${target} REUSE_FROM labkit_student_pch)
  else()
    target_precompile_headers(${target} REUSE_FROM labkit_geometry)
  endif()
endfunction()

# Every lab grading/manifest.json lists, in its order: the manifest is the one list of
# the labs, so that adding lab 08 is its entry there and its files, and no line here.
function(labkit_add_labs)
  set(json "${LABKIT_MANIFEST}")
  string(JSON lab_count LENGTH "${json}" labs)
  math(EXPR last "${lab_count} - 1")
  foreach(i RANGE ${last})
    string(JSON id GET "${json}" labs ${i} id)
    string(JSON name GET "${json}" labs ${i} name)
    if(NOT id MATCHES "^[0-9][0-9]$" OR NOT name MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "grading/manifest.json: lab ${i} has id '${id}' and name '${name}'; an id is two digits "
                          "(\"08\") and a name lower case letters, digits and _ (\"boxes\")")
    endif()
    foreach(file IN ITEMS "labs/${id}_${name}/${name}.h" "tests/${id}_${name}/test.cpp")
      if(NOT EXISTS "${PROJECT_SOURCE_DIR}/${file}")
        message(FATAL_ERROR "grading/manifest.json lists lab ${id} (${name}), but ${file} is missing "
                            "(README, \"Adding a lab\")")
      endif()
    endforeach()
    labkit_add_lab(${id} ${name})
  endforeach()
endfunction()

# Lab NN's targets, from its files: the implementations (the student's file, the
# reference), its checker (judge, generators, calls, the test program), an answerer for
# each implementation, what `./labkit grade` reads, and its tests (the reference's steps,
# the fakes, the mutants). Each part is a function below.
function(labkit_add_lab number name)
  set(stem ${number}_${name})
  labkit_lab_implementations(${number} ${name})
  labkit_lab_checker(${number} ${name})
  foreach(impl IN LISTS implementations)
    labkit_add_answerer(${number} ${name} ${impl} lab${number}_${impl})
  endforeach()
  labkit_lab_grading(${number} ${name})
  if(TARGET lab${number}_reference)
    labkit_lab_tests(${number} ${name})
  endif()

  set_property(GLOBAL APPEND PROPERTY LABKIT_LABS ${stem})
  if(EXISTS "${PROJECT_SOURCE_DIR}/viewer/scenes/${stem}.cpp")
    set_property(GLOBAL APPEND PROPERTY LABKIT_SCENES ${stem})
  endif()
endfunction()

# The lab's list of calls (tests/NN_name/queries.h), expanded on both sides of the pipe:
# the definitions that select it, in `out`.
function(labkit_lab_query_definitions number name out)
  set(${out} LABKIT_LAB_QUERIES="${number}_${name}/queries.h" LABKIT_LAB_NAMESPACE=lab${number}
      LABKIT_LAB_CALLS=LABKIT_LAB${number}_CALLS PARENT_SCOPE)
endfunction()

# The lab's given code, the student's library and the reference's; `implementations`
# (in the caller) lists those that exist: student, and reference when solutions/ has it.
function(labkit_lab_implementations number name)
  set(stem ${number}_${name})
  set(lab lab${number})
  # The lab's given code, if it has any (tests/NN_name/given*.cpp): plain functions its
  # header declares as ready tools, linked with every implementation of the lab.
  file(GLOB given_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/tests/${stem}/given*.cpp")
  if(given_sources)
    add_library(given_${stem} STATIC ${given_sources})
    target_link_libraries(given_${stem} PUBLIC labkit_geometry labkit_given)
  endif()

  file(GLOB student_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/labs/${stem}/*.cpp")
  labkit_implementation(${lab}_student ${stem} STUDENT ${student_sources})
  # The student's file may include only its lab's header, the geometry types, Eigen and
  # the standard library: its compile goes through the audit ./labkit grade applies
  # (runner/includes.h), so that a file the grader refuses fails here too, saying why.
  set_target_properties(${lab}_student PROPERTIES CXX_COMPILER_LAUNCHER
    "$<TARGET_FILE:labkit-runner>;lab-compile;--kit;${PROJECT_SOURCE_DIR};--lab;${PROJECT_SOURCE_DIR}/labs/${stem};--")
  add_dependencies(${lab}_student labkit-runner)

  set(implementations student)
  if(EXISTS "${PROJECT_SOURCE_DIR}/solutions/${stem}")
    file(GLOB reference_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/solutions/${stem}/*.cpp")
    labkit_implementation(${lab}_reference ${stem} ${reference_sources})
    labkit_kit_code(${lab}_reference)
    list(APPEND implementations reference)
  endif()
  set(implementations ${implementations} PARENT_SCOPE)
endfunction()

# The lab's checker: the judge's and the generators' libraries, the calls on the judge's
# side, the answerer's main(), and the test program.
function(labkit_lab_checker number name)
  set(stem ${number}_${name})
  set(lab lab${number})
  # The judge: its verdicts (tests/NN_name/judge*.cpp, split by step when long). Then the
  # lab's own generators (tests/NN_name/generators*.cpp), which know the lab's types: a
  # library of their own, since the viewer judges without drawing random cases, and they
  # are half of what a checker costs to build (the viewer's first build waits for them).
  file(GLOB judge_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/tests/${stem}/judge*.cpp")
  file(GLOB generators_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/tests/${stem}/generators*.cpp")
  foreach(part judge generators)
    add_library(${lab}_${part} STATIC ${${part}_sources})
    target_include_directories(${lab}_${part} PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}" "${PROJECT_SOURCE_DIR}/tests")
    target_link_libraries(${lab}_${part} PUBLIC labkit_harness labkit_oracle)
    if(TARGET given_${stem})
      target_link_libraries(${lab}_${part} PUBLIC given_${stem})
    endif()
    labkit_kit_code(${lab}_${part})
    target_precompile_headers(${lab}_${part} REUSE_FROM labkit_judge_pch)
  endforeach()
  target_link_libraries(${lab}_generators PUBLIC ${lab}_judge labkit_generators)  # judge.h's helpers (scale_of, ...)

  # The lab's list of calls (tests/NN_name/queries.h), expanded on both sides of the pipe.
  labkit_lab_query_definitions(${number} ${name} query_definitions)
  add_library(${lab}_calls STATIC "${PROJECT_SOURCE_DIR}/common/protocol/lab_calls.cpp")
  target_compile_definitions(${lab}_calls PRIVATE ${query_definitions})
  target_include_directories(${lab}_calls PRIVATE "${PROJECT_SOURCE_DIR}/labs/${stem}" "${PROJECT_SOURCE_DIR}/tests")
  target_link_libraries(${lab}_calls PUBLIC labkit_protocol)
  if(TARGET given_${stem})
    target_link_libraries(${lab}_calls PUBLIC given_${stem})
  endif()
  add_library(${lab}_answerer_main OBJECT "${PROJECT_SOURCE_DIR}/common/protocol/lab_answerer.cpp")
  target_compile_definitions(${lab}_answerer_main PRIVATE ${query_definitions})
  target_include_directories(${lab}_answerer_main PRIVATE "${PROJECT_SOURCE_DIR}/labs/${stem}" "${PROJECT_SOURCE_DIR}/tests")
  target_link_libraries(${lab}_answerer_main PUBLIC labkit_protocol)
  labkit_kit_code(${lab}_answerer_main)

  add_executable(test_${stem} "${PROJECT_SOURCE_DIR}/tests/${stem}/test.cpp")
  target_link_libraries(test_${stem} PRIVATE ${lab}_judge ${lab}_generators ${lab}_calls labkit_catch_main)
  labkit_kit_code(test_${stem} -Og)
  target_precompile_headers(test_${stem} REUSE_FROM labkit_test_pch)
  labkit_kit_code(${lab}_calls)
endfunction()

# `./labkit grade` builds a submission's answerer by compiling its file(s) as the stub
# is compiled (compile_commands.json) and linking them as the stub's answerer is linked:
# that link command is recorded each time the kit runs it.
function(labkit_lab_grading number name)
  set(stem ${number}_${name})
  set(lab lab${number})
  set(link_record "${PROJECT_BINARY_DIR}/grading/${stem}.link")
  set_target_properties(answer_${stem}_student PROPERTIES
    CXX_LINKER_LAUNCHER "${PROJECT_SOURCE_DIR}/cmake/record-command.sh;${link_record}")
  file(GENERATE OUTPUT "${PROJECT_BINARY_DIR}/grading/${stem}.json" CONTENT
    "{\"lab\": \"${number}\", \"student_library\": \"$<TARGET_FILE:${lab}_student>\", \"link_record\": \"${link_record}\"}\n")
  set_property(GLOBAL APPEND PROPERTY LABKIT_GRADING_TARGETS answer_${stem}_student test_${stem})
endfunction()

# The reference's tests: one per step, the contract, the fakes and the mutants.
function(labkit_lab_tests number name)
  set(stem ${number}_${name})
  set(lab lab${number})
  # One test per step. Each leaves its harness report in build/reports/, which
  # `labkit-runner report` sums up after the suite, and checks that every random case it
  # draws lies in the header's input domain (LABKIT_DOMAIN_AUDIT).
  labkit_manifest_steps(${number} steps)
  file(MAKE_DIRECTORY "${PROJECT_BINARY_DIR}/reports")
  foreach(step IN LISTS steps)
    add_test(NAME ${lab}.step${step} COMMAND test_${stem} "[${lab}][step${step}]")
    set_tests_properties(${lab}.step${step} PROPERTIES LABELS "reference;${lab}" FIXTURES_SETUP labkit_reports
      ENVIRONMENT "LABKIT_REPORT=${PROJECT_BINARY_DIR}/reports/${lab}.step${step}.json;LABKIT_ANSWERER=$<TARGET_FILE:answer_${stem}_reference>;LABKIT_DOMAIN_AUDIT=1")
  endforeach()
  # The header's preconditions: the reference rejects every kind of invalid input with
  # std::invalid_argument naming the argument. Tagged [contract], in no step: students
  # are not graded on invalid input unless a step says so.
  add_test(NAME ${lab}.contract COMMAND test_${stem} "[${lab}][contract]")
  set_tests_properties(${lab}.contract PROPERTIES LABELS "reference;${lab}"
    ENVIRONMENT "LABKIT_ANSWERER=$<TARGET_FILE:answer_${stem}_reference>")

  # The kit's test of its scoring and of its judges (runner/fake.h): answerers that do
  # no geometry must earn nothing, and no judge may fail on their answers.
  labkit_lab_query_definitions(${number} ${name} query_definitions)
  add_executable(answer_${stem}_fake "${PROJECT_SOURCE_DIR}/tests/kit/fake_answerer.cpp")
  target_compile_definitions(answer_${stem}_fake PRIVATE ${query_definitions})
  target_include_directories(answer_${stem}_fake PRIVATE "${PROJECT_SOURCE_DIR}/labs/${stem}" "${PROJECT_SOURCE_DIR}/tests")
  target_link_libraries(answer_${stem}_fake PRIVATE labkit_protocol ${lab}_reference)
  labkit_kit_code(answer_${stem}_fake)
  foreach(answers nothing random examples garbage)
    add_test(NAME kit.fake.${lab}.${answers} COMMAND labkit-runner fake ${number} --answers ${answers})
    set_tests_properties(kit.fake.${lab}.${answers} PROPERTIES LABELS "kit;fake;${lab}")
  endforeach()

  # The classic mistakes, each of which the tests must catch.
  labkit_add_mutants(${number} ${name})
endfunction()

# The answerer of lab NN for one implementation (a library target): the lab's functions
# and nothing of the judge's.
function(labkit_add_answerer number name suffix implementation)
  set(target answer_${number}_${name}_${suffix})
  add_executable(${target} $<TARGET_OBJECTS:lab${number}_answerer_main>)
  target_link_libraries(${target} PRIVATE lab${number}_answerer_main ${implementation})
endfunction()

# The step numbers of lab NN in grading/manifest.json.
function(labkit_manifest_steps number out)
  string(JSON lab_count LENGTH "${LABKIT_MANIFEST}" labs)
  math(EXPR last "${lab_count} - 1")
  set(result "")
  foreach(i RANGE ${last})
    string(JSON id GET "${LABKIT_MANIFEST}" labs ${i} id)
    if(id STREQUAL number)
      string(JSON step_count LENGTH "${LABKIT_MANIFEST}" labs ${i} steps)
      math(EXPR last_step "${step_count} - 1")
      foreach(k RANGE ${last_step})
        string(JSON step GET "${LABKIT_MANIFEST}" labs ${i} steps ${k} step)
        list(APPEND result ${step})
      endforeach()
    endif()
  endforeach()
  if(NOT result)
    message(FATAL_ERROR "grading/manifest.json has no steps for lab ${number}")
  endif()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The classic mistakes of lab NN, each written in the reference where it goes
# (cmake/Mutants.cmake): each mutant is the reference with that one mistake in it, its own
# answerer, and a test that runs the lab's steps against it in order (runner/mutant.h).
# This is how the kit shows that its tests fail, in the right step, for the mistakes
# students actually make, and say so in the lab's words.
include("${CMAKE_CURRENT_LIST_DIR}/Mutants.cmake")

function(labkit_add_mutants number name)
  set(stem ${number}_${name})
  set(source "${PROJECT_SOURCE_DIR}/solutions/${stem}/${name}.cpp")
  set(where "solutions/${stem}/${name}.cpp")
  file(READ "${source}" reference)
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")
  labkit_mutant_specs(m "${reference}" "${where}")
  labkit_manifest_steps(${number} steps)
  list(JOIN steps ", " listed)
  foreach(mutant IN LISTS m_names)
    if(NOT m_${mutant}_step IN_LIST steps)
      message(FATAL_ERROR "${m_${mutant}_line_0}: mutant '${mutant}' is a mistake of step ${m_${mutant}_step}, "
                          "which lab ${number} does not have (grading/manifest.json: steps ${listed})")
    endif()
    labkit_mutant_source(mutated m ${mutant} "${reference}" "${where}")
    set(output "${PROJECT_BINARY_DIR}/mutants/${stem}/${mutant}.cpp")
    # Rewritten only when it changes, so that a reconfigure does not rebuild every mutant.
    set(old "")
    if(EXISTS "${output}")
      file(READ "${output}" old)
    endif()
    if(NOT old STREQUAL mutated)
      file(WRITE "${output}" "${mutated}")
    endif()

    set(library lab${number}_mutant_${mutant})
    labkit_implementation(${library} ${stem} "${output}")
    target_compile_options(${library} PRIVATE -w)  # a mistake may well leave a variable unused
    labkit_kit_code(${library})
    set_target_properties(${library} PROPERTIES EXCLUDE_FROM_ALL FALSE)
    labkit_add_answerer(${number} ${name} mutant_${mutant} ${library})
    set(says "")
    foreach(word IN LISTS m_${mutant}_says)
      list(APPEND says --says "${word}")
    endforeach()
    add_test(NAME lab${number}.mutant.${mutant}
             COMMAND labkit-runner mutant ${number} --name ${mutant} --step ${m_${mutant}_step} ${says})
    set_tests_properties(lab${number}.mutant.${mutant} PROPERTIES LABELS "mutant;lab${number}"
      ENVIRONMENT "LABKIT_BUILD_DIR=${PROJECT_BINARY_DIR}")
  endforeach()
endfunction()
