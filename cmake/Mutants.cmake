# The classic mistakes, written where they go: in the reference itself. A mutant is one
# comment line (or a few, each continuation indented by two more spaces) just above the
# code it edits:
#
#   // mutant touching_is_clear (step 1, "touching counts"): `<=` -> `<`
#   return (a.center - b.center).squaredNorm() <= reach * reach;
#
# The mutant is the reference with the text between the first backquotes replaced by the
# text between the second, in the code below the comment block, up to the next blank line
# or the next mutant's comment (its window); that text must appear there exactly once,
# spaces and line breaks aside. So reformatting the code, or rewording any comment, never
# breaks a mutant, and the configure refuses a mutant it cannot place, naming the line.
# The same name on several lines edits each place (the mistake made at each of them); its
# edit, step and words are then the same on every line, and its step one the manifest
# lists. ctest runs the lab's steps against each mutant in order and expects the steps
# before its step to pass, its step to FAIL, and the why of that first failure to hold
# each quoted word (the concept the mistake breaks).
#
# labkit_mutant_specs(prefix text where): reads every mutant of `text` into variables of
#   the caller: ${prefix}_names, and for each name N: ${prefix}_N_step, ${prefix}_N_says
#   (a list), ${prefix}_N_count and, for each of its places k, ${prefix}_N_find_k,
#   ${prefix}_N_replace_k, ${prefix}_N_begin_k, ${prefix}_N_end_k (the window's offsets).
# labkit_mutant_source(out prefix name text where): `text` with mutant `name` written in.
# Tested by tests/kit/mutants.test.sh.

set(LABKIT_MUTANT_FORM "// mutant NAME (step K, \"word\", ...): `text` -> `replacement`")
set(LABKIT_MUTANT_REGEX "^mutant ([a-z][a-z0-9_]*) \\(step ([0-9]+)((, \"[^\"]+\")+)\\): `([^`]*)` -> `([^`]*)`$")

# The 1-based line of offset `at` in `text`, as "where:line".
function(labkit_mutant_line out text at where)
  string(SUBSTRING "${text}" 0 ${at} before)
  string(REGEX MATCHALL "\n" breaks "${before}")
  list(LENGTH breaks line)
  math(EXPR line "${line} + 1")
  set(${out} "${where}:${line}" PARENT_SCOPE)
endfunction()

# One mutant's line at `position` of `text` (the offset of the line break before it): its
# spec, joined with its continuation lines (`//` and three or more spaces) until whole,
# and the offset where it ends. Stops the configure when it is not whole by then.
function(labkit_mutant_read spec_out end_out text position line)
  string(SUBSTRING "${text}" ${position} -1 rest)
  string(REGEX MATCH "^\n[ \t]*// mutant [^\n]*" marker "${rest}")
  string(REGEX REPLACE "^\n[ \t]*// " "" spec "${marker}")
  string(LENGTH "${marker}" length)
  math(EXPR position "${position} + ${length}")
  while(NOT spec MATCHES "${LABKIT_MUTANT_REGEX}")
    string(SUBSTRING "${text}" ${position} -1 rest)
    string(REGEX MATCH "^\n[ \t]*//   +[^\n]*" more "${rest}")
    if(more STREQUAL "")
      message(FATAL_ERROR "${line}: a mutant is written ${LABKIT_MUTANT_FORM} (continued on lines `//   ...`), "
                          "not `// ${spec}`")
    endif()
    string(REGEX REPLACE "^\n[ \t]*//   +" "" words "${more}")
    set(spec "${spec} ${words}")
    string(LENGTH "${more}" length)
    math(EXPR position "${position} + ${length}")
  endwhile()
  set(${spec_out} "${spec}" PARENT_SCOPE)
  set(${end_out} ${position} PARENT_SCOPE)
endfunction()

# The window of the mutant whose line ends at `position`: from the first line of code
# after its comment block to the next blank line, or to the first comment line above the
# next mutant, whichever comes first.
function(labkit_mutant_window begin_out end_out text position)
  string(SUBSTRING "${text}" ${position} -1 rest)
  string(REGEX MATCH "^(\n[ \t]*//[^\n]*)*\n" block "${rest}")
  string(LENGTH "${block}" length)
  math(EXPR begin "${position} + ${length}")
  string(SUBSTRING "${text}" ${begin} -1 rest)
  string(FIND "${rest}" "\n\n" end)
  string(REGEX MATCH "\n[ \t]*// mutant " next "${rest}")
  if(NOT next STREQUAL "")
    string(FIND "${rest}" "${next}" next)
    string(SUBSTRING "${rest}" 0 ${next} before_next)
    string(REGEX MATCH "(\n[ \t]*//[^\n]*)+$" comments "${before_next}")
    string(LENGTH "${comments}" length)
    math(EXPR next "${next} - ${length}")
    if(end EQUAL -1 OR next LESS end)
      set(end ${next})
    endif()
  endif()
  if(end EQUAL -1)
    string(LENGTH "${rest}" end)
  endif()
  math(EXPR end "${begin} + ${end}")
  set(${begin_out} ${begin} PARENT_SCOPE)
  set(${end_out} ${end} PARENT_SCOPE)
endfunction()

function(labkit_mutant_specs prefix text where)
  string(REGEX MATCH "// mutants?:[^\n]*" old "${text}")
  if(NOT old STREQUAL "")
    string(FIND "${text}" "${old}" at)
    labkit_mutant_line(line "${text}" ${at} "${where}")
    message(FATAL_ERROR "${line}: `${old}` is the old form of a mutant; write it as ${LABKIT_MUTANT_FORM}")
  endif()
  # A line break in front, so that a mutant on the first line is found as any other is;
  # the offsets kept are those of the text as given.
  set(text "\n${text}")
  set(names "")
  set(position 0)
  while(TRUE)
    string(SUBSTRING "${text}" ${position} -1 rest)
    string(REGEX MATCH "\n[ \t]*// mutant " marker "${rest}")
    if(marker STREQUAL "")
      break()
    endif()
    string(FIND "${rest}" "${marker}" at)
    math(EXPR position "${position} + ${at}")
    labkit_mutant_line(line "${text}" ${position} "${where}")
    labkit_mutant_read(spec position "${text}" ${position} "${line}")
    string(REGEX MATCH "${LABKIT_MUTANT_REGEX}" spec "${spec}")
    set(name "${CMAKE_MATCH_1}")
    set(step "${CMAKE_MATCH_2}")
    set(quoted "${CMAKE_MATCH_3}")
    set(find "${CMAKE_MATCH_5}")
    set(replace "${CMAKE_MATCH_6}")
    string(REGEX MATCHALL "\"[^\"]+\"" quoted "${quoted}")
    string(REGEX REPLACE "[ \t\n]+" "" compact "${find}")
    if(compact STREQUAL "")
      message(FATAL_ERROR "${line}: mutant '${name}' names no text to replace (between the first backquotes)")
    endif()
    set(says "")
    foreach(word IN LISTS quoted)
      string(REGEX REPLACE "^\"(.*)\"$" "\\1" word "${word}")
      list(APPEND says "${word}")
    endforeach()
    labkit_mutant_window(begin end "${text}" ${position})

    if(name IN_LIST names)
      # The same mistake at another place: the same edit, step and words, or it is a
      # second mistake that needs a name of its own.
      if(NOT step STREQUAL "${${prefix}_${name}_step}" OR NOT says STREQUAL "${${prefix}_${name}_says}" OR
         NOT find STREQUAL "${${prefix}_${name}_find}" OR NOT replace STREQUAL "${${prefix}_${name}_replace}")
        message(FATAL_ERROR "${line}: mutant '${name}' appears again with another edit, step or words; one "
                            "mistake makes the same edit at each of its places: give a different one its own name")
      endif()
      set(k ${${prefix}_${name}_count})
    else()
      list(APPEND names ${name})
      set(${prefix}_${name}_step "${step}")
      set(${prefix}_${name}_says "${says}")
      set(${prefix}_${name}_find "${find}")
      set(${prefix}_${name}_replace "${replace}")
      set(${prefix}_${name}_step "${step}" PARENT_SCOPE)
      set(${prefix}_${name}_says "${says}" PARENT_SCOPE)
      set(k 0)
    endif()
    set(${prefix}_${name}_find_${k} "${find}" PARENT_SCOPE)
    set(${prefix}_${name}_replace_${k} "${replace}" PARENT_SCOPE)
    math(EXPR begin "${begin} - 1")
    math(EXPR end "${end} - 1")
    set(${prefix}_${name}_begin_${k} ${begin} PARENT_SCOPE)
    set(${prefix}_${name}_end_${k} ${end} PARENT_SCOPE)
    set(${prefix}_${name}_line_${k} "${line}" PARENT_SCOPE)
    math(EXPR k "${k} + 1")
    set(${prefix}_${name}_count ${k})
    set(${prefix}_${name}_count ${k} PARENT_SCOPE)
  endwhile()
  set(${prefix}_names "${names}" PARENT_SCOPE)
endfunction()

function(labkit_mutant_source out prefix name text where)
  set(count ${${prefix}_${name}_count})
  math(EXPR last "${count} - 1")
  # The last place first, so that the earlier places' offsets still hold.
  set(places "")
  foreach(k RANGE ${last})
    list(PREPEND places ${k})
  endforeach()
  foreach(k IN LISTS places)
    set(find "${${prefix}_${name}_find_${k}}")
    set(line "${${prefix}_${name}_line_${k}}")
    set(begin ${${prefix}_${name}_begin_${k}})
    math(EXPR length "${${prefix}_${name}_end_${k}} - ${begin}")
    string(SUBSTRING "${text}" ${begin} ${length} window)
    # The text as a pattern: its characters in order, regex-escaped, any spacing between.
    string(REGEX REPLACE "[ \t\n]+" "" compact "${find}")
    string(REGEX REPLACE "([][\\\\^$.|?*+(){}])" "\\\\\\1" escaped "${compact}")
    string(REGEX REPLACE "(\\\\?.)" "\\1[ \t\n]*" pattern "${escaped}")
    string(REGEX REPLACE "\\[ \t\n\\]\\*$" "" pattern "${pattern}")
    string(REGEX MATCH "${pattern}" found "${window}")
    if(found STREQUAL "")
      message(FATAL_ERROR "${line}: mutant '${name}': `${find}` is not in the code below it "
                          "(up to the next blank line or mutant)")
    endif()
    string(FIND "${window}" "${found}" found_at)
    string(LENGTH "${found}" found_length)
    math(EXPR found_end "${found_at} + ${found_length}")
    string(SUBSTRING "${window}" ${found_end} -1 window_rest)
    string(REGEX MATCH "${pattern}" twice "${window_rest}")
    if(NOT twice STREQUAL "")
      message(FATAL_ERROR "${line}: mutant '${name}': `${find}` appears twice in the code below it; "
                          "quote more of it, so that it names one place")
    endif()
    string(SUBSTRING "${window}" 0 ${found_at} window_head)
    string(SUBSTRING "${text}" 0 ${begin} head)
    math(EXPR tail_start "${begin} + ${length}")
    string(SUBSTRING "${text}" ${tail_start} -1 tail)
    set(text "${head}${window_head}${${prefix}_${name}_replace_${k}}${window_rest}${tail}")
  endforeach()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
