# Lab and step titles come from grading/manifest.json alone: this writes them into
# generated/labkit_titles.h at configure time (and again whenever the manifest changes),
# for the tests' names (LABKIT_STEP in common/harness/titles.h) and the viewer's list.
function(labkit_write_titles manifest output)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${manifest}")
  file(READ "${manifest}" json)
  set(text "// Written by cmake/Titles.cmake from grading/manifest.json: edit the manifest, not this.\n#pragma once\n\n")
  string(JSON lab_count LENGTH "${json}" labs)
  math(EXPR last_lab "${lab_count} - 1")
  foreach(i RANGE ${last_lab})
    string(JSON id GET "${json}" labs ${i} id)
    string(JSON title GET "${json}" labs ${i} title)
    labkit_c_string(title)
    string(APPEND text "#define LABKIT_LAB_TITLE_${id} ${title}\n")
    string(JSON step_count LENGTH "${json}" labs ${i} steps)
    math(EXPR last_step "${step_count} - 1")
    foreach(k RANGE ${last_step})
      string(JSON tag GET "${json}" labs ${i} steps ${k} tag)
      string(JSON step_title GET "${json}" labs ${i} steps ${k} title)
      labkit_c_string(step_title)
      string(APPEND text "#define LABKIT_TITLE_${tag} ${step_title}\n")
    endforeach()
  endforeach()
  # Rewritten only when it changes, so that a configure does not rebuild every test.
  file(CONFIGURE OUTPUT "${output}" CONTENT "${text}" @ONLY)
endfunction()

# `variable` as a C string literal.
macro(labkit_c_string variable)
  string(REPLACE "\\" "\\\\" ${variable} "${${variable}}")
  string(REPLACE "\"" "\\\"" ${variable} "${${variable}}")
  set(${variable} "\"${${variable}}\"")
endmacro()
