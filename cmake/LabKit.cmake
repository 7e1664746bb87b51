# labkit_add_lab(NN name): everything one lab needs, from its files alone.
#
#   labs/NN_name/*.cpp            -> labNN_student     (the student's file: one small object)
#   solutions/NN_name/*.cpp       -> labNN_reference   (absent in a student release)
#   tests/NN_name.judge.cpp       -> labNN_judge       (verdicts against the oracle; the viewer shares it)
#   tests/NN_name.test.cpp        -> compiled once, linked twice:
#                                    test_NN_name_student and test_NN_name_reference
#   grading record                -> build/grading/NN_name.{json,link}: how ./labkit grade
#                                    links a submission (see runner/lab_build.h)
#   tests/NN_name.mutants.cmake   -> the reference with one classic mistake each; ctest
#                                    expects the step each one breaks to fail
#   viewer/scenes/NN_name.cpp     -> the lab's viewer scene, compiled into both viewers
#                                    (viewer/CMakeLists.txt; its line in viewer/scenes/scenes.h)
#
# ctest runs each step of the reference as its own test, "labNN.stepK", with the steps
# read from grading/manifest.json.
file(READ "${PROJECT_SOURCE_DIR}/grading/manifest.json" LABKIT_MANIFEST)

function(labkit_add_lab number name)
  set(stem ${number}_${name})
  set(lab lab${number})

  file(GLOB student_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/labs/${stem}/*.cpp")
  add_library(${lab}_student STATIC ${student_sources})
  target_include_directories(${lab}_student PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
  target_link_libraries(${lab}_student PUBLIC labkit_geometry labkit_given)
  target_precompile_headers(${lab}_student REUSE_FROM labkit_geometry)

  set(implementations student)
  if(EXISTS "${PROJECT_SOURCE_DIR}/solutions/${stem}")
    file(GLOB reference_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/solutions/${stem}/*.cpp")
    add_library(${lab}_reference STATIC ${reference_sources})
    target_include_directories(${lab}_reference PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
    target_link_libraries(${lab}_reference PUBLIC labkit_geometry labkit_given)
    target_precompile_headers(${lab}_reference REUSE_FROM labkit_geometry)
    list(APPEND implementations reference)
  endif()

  add_library(${lab}_judge STATIC "${PROJECT_SOURCE_DIR}/tests/${stem}.judge.cpp")
  target_include_directories(${lab}_judge PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
  target_link_libraries(${lab}_judge PUBLIC labkit_harness labkit_oracle)

  add_library(${lab}_tests OBJECT "${PROJECT_SOURCE_DIR}/tests/${stem}.test.cpp")
  target_link_libraries(${lab}_tests PUBLIC ${lab}_judge)
  target_include_directories(${lab}_tests PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")

  foreach(impl IN LISTS implementations)
    labkit_add_test_binary(${number} ${name} ${impl} ${lab}_${impl})
  endforeach()

  # `./labkit grade` builds a submission's lab by compiling its file(s) as the stub is
  # compiled (compile_commands.json) and linking them as the stub's test binary is
  # linked: that link command is recorded each time the kit runs it.
  set(link_record "${PROJECT_BINARY_DIR}/grading/${stem}.link")
  set_target_properties(test_${stem}_student PROPERTIES
    CXX_LINKER_LAUNCHER "${PROJECT_SOURCE_DIR}/cmake/record-command.sh;${link_record}")
  file(GENERATE OUTPUT "${PROJECT_BINARY_DIR}/grading/${stem}.json" CONTENT
    "{\"lab\": \"${number}\", \"student_library\": \"$<TARGET_FILE:${lab}_student>\", \"link_record\": \"${link_record}\"}\n")
  set_property(GLOBAL APPEND PROPERTY LABKIT_GRADING_TARGETS test_${stem}_student)

  # ctest: one test per step of the reference. Each leaves its harness report in
  # build/reports/, which `labkit-runner report` sums up after the suite.
  if(TARGET ${lab}_reference)
    labkit_manifest_steps(${number} steps)
    file(MAKE_DIRECTORY "${PROJECT_BINARY_DIR}/reports")
    foreach(step IN LISTS steps)
      add_test(NAME ${lab}.step${step} COMMAND test_${stem}_reference "[${lab}][step${step}]")
      set_tests_properties(${lab}.step${step} PROPERTIES LABELS "reference;${lab}"
        ENVIRONMENT "LABKIT_REPORT=${PROJECT_BINARY_DIR}/reports/${lab}.step${step}.json")
    endforeach()
  endif()

  # The classic mistakes, each of which the tests must catch.
  if(TARGET ${lab}_reference AND EXISTS "${PROJECT_SOURCE_DIR}/tests/${stem}.mutants.cmake")
    include("${PROJECT_SOURCE_DIR}/tests/${stem}.mutants.cmake")
  endif()

  set_property(GLOBAL APPEND PROPERTY LABKIT_LABS ${stem})
  if(EXISTS "${PROJECT_SOURCE_DIR}/viewer/scenes/${stem}.cpp")
    set_property(GLOBAL APPEND PROPERTY LABKIT_SCENES ${stem})
  endif()
endfunction()

# A test binary of lab NN linked against one implementation (a library target).
function(labkit_add_test_binary number name suffix implementation)
  set(target test_${number}_${name}_${suffix})
  add_executable(${target} $<TARGET_OBJECTS:lab${number}_tests>)
  target_link_libraries(${target} PRIVATE lab${number}_tests ${implementation} labkit_catch_main)
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

# labkit_mutant(NN name NAME id STEP k FIND "text" REPLACE "text" [FILE solution.cpp])
#
# A mutant is the reference solution with one classic mistake written in (the handout's
# "classic mistake" of that step): the text FIND replaced by REPLACE. ctest then expects
# step k of the lab to FAIL against it: this is how the kit shows that its tests can
# fail, and fail for the mistakes students actually make. Mutants live beside the
# lab's tests, in tests/NN_name.mutants.cmake.
function(labkit_mutant number name)
  # PARSE_ARGV keeps the semicolons of C++ code inside FIND and REPLACE.
  cmake_parse_arguments(PARSE_ARGV 2 M "" "NAME;STEP;FILE;FIND;REPLACE" "")
  set(stem ${number}_${name})
  if(NOT M_FILE)
    set(M_FILE ${name}.cpp)
  endif()
  set(source "${PROJECT_SOURCE_DIR}/solutions/${stem}/${M_FILE}")
  file(READ "${source}" text)
  string(FIND "${text}" "${M_FIND}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "mutant '${M_NAME}' of lab ${number}: its FIND text no longer appears in "
                        "solutions/${stem}/${M_FILE}; update tests/${stem}.mutants.cmake")
  endif()
  string(REPLACE "${M_FIND}" "${M_REPLACE}" mutated "${text}")
  set(output "${PROJECT_BINARY_DIR}/mutants/${stem}/${M_NAME}.cpp")
  # Rewritten only when it changes, so that a reconfigure does not rebuild every mutant.
  set(old "")
  if(EXISTS "${output}")
    file(READ "${output}" old)
  endif()
  if(NOT old STREQUAL mutated)
    file(WRITE "${output}" "${mutated}")
  endif()
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")

  set(library lab${number}_mutant_${M_NAME})
  add_library(${library} STATIC "${output}")
  target_include_directories(${library} PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
  target_link_libraries(${library} PUBLIC labkit_geometry labkit_given)
  target_precompile_headers(${library} REUSE_FROM labkit_geometry)
  target_compile_options(${library} PRIVATE -w)  # a mistake may well leave a variable unused
  set_target_properties(${library} PROPERTIES EXCLUDE_FROM_ALL FALSE)
  labkit_add_test_binary(${number} ${name} mutant_${M_NAME} ${library})
  # Caught when the step fails in any way: a failed check, or a crash (a mistake may
  # divide by zero; CTest's WILL_FAIL would not count a signal as a failure).
  add_test(NAME lab${number}.mutant.${M_NAME}
           COMMAND sh -c "! \"$0\" \"$1\"" $<TARGET_FILE:test_${stem}_mutant_${M_NAME}> "[lab${number}][step${M_STEP}]")
  set_tests_properties(lab${number}.mutant.${M_NAME} PROPERTIES LABELS "mutant;lab${number}")
endfunction()
