# labkit_add_lab(NN name): everything one lab needs, from its files alone.
#
#   labs/NN_name/*.cpp            -> labNN_student     (the student's file: one small object)
#   solutions/NN_name/*.cpp       -> labNN_reference   (absent in a student release)
#   tests/NN_name.judge.cpp       -> labNN_judge       (verdicts against the oracle; the viewer shares it)
#   tests/NN_name.test.cpp        -> compiled once, linked twice:
#                                    test_NN_name_student and test_NN_name_reference
#   viewer/scenes/NN_name.cpp     -> the lab's viewer scene (see viewer/CMakeLists.txt)
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
  target_link_libraries(${lab}_student PUBLIC labkit_geometry)
  target_precompile_headers(${lab}_student REUSE_FROM labkit_geometry)

  set(implementations student)
  if(EXISTS "${PROJECT_SOURCE_DIR}/solutions/${stem}")
    file(GLOB reference_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/solutions/${stem}/*.cpp")
    add_library(${lab}_reference STATIC ${reference_sources})
    target_include_directories(${lab}_reference PUBLIC "${PROJECT_SOURCE_DIR}/labs/${stem}")
    target_link_libraries(${lab}_reference PUBLIC labkit_geometry)
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

  # ctest: one test per step of the reference.
  if(TARGET ${lab}_reference)
    labkit_manifest_steps(${number} steps)
    foreach(step IN LISTS steps)
      add_test(NAME ${lab}.step${step} COMMAND test_${stem}_reference "[${lab}][step${step}]")
      set_tests_properties(${lab}.step${step} PROPERTIES LABELS "reference;${lab}")
    endforeach()
  endif()

  set_property(GLOBAL APPEND PROPERTY LABKIT_LABS ${stem})
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
