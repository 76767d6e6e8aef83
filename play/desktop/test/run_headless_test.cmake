# The desktop demo without a display (cmake -P; play/desktop/README.md):
#   1. session.script for 420 frames: the world's state hash equals that of `edgeland replay`
#      of the edit log the session wrote (the library replaying the same edits); no body's centre
#      was ever inside solid material after a step; every tool made its edit, undo and redo ran;
#      the piece of rock the script digs a ring around was detached as debris, and no island was
#      ever left in the landscape after an edit;
#      bodies are still in the world; the screenshot is not blank (png_colours counts its
#      colours, apart from the program that drew it).
#   2. save_load.script: F5 then edits then F9: the loaded world's state hash is the saved one.
#   PLAY, EDGELAND, PNG_COLOURS: the programs;  SCRIPTS: the scripts' folder;  WORK: scratch
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(run_play script frames out)
  execute_process(COMMAND "${PLAY}" --headless --script "${SCRIPTS}/${script}" --frames ${frames}
    --screenshot "${WORK}/${script}.png" --log-out "${WORK}/${script}.log"
    --save-file "${WORK}/${script}.save"
    RESULT_VARIABLE status OUTPUT_VARIABLE json ERROR_VARIABLE err TIMEOUT 500)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "edgeland-play ${script}: exit ${status}\n${json}${err}")
  endif()
  message(STATUS "${script}: ${json}")
  set(${out} "${json}" PARENT_SCOPE)
endfunction()

# expect(MESSAGE CONDITION...): fails with MESSAGE unless the if() condition holds.
macro(expect what)
  if(NOT (${ARGN}))
    message(FATAL_ERROR "${what}")
  endif()
endmacro()

# 1. The scripted session.
run_play(session.script 420 session)
execute_process(COMMAND "${EDGELAND}" replay "${WORK}/session.script.log"
  RESULT_VARIABLE status OUTPUT_VARIABLE native ERROR_VARIABLE err)
expect("edgeland replay of the session's log: exit ${status}\n${err}"
  status EQUAL 0)
string(JSON native_hash GET "${native}" state_hash)
string(JSON play_hash GET "${session}" state_hash)
expect("state hash: edgeland-play ${play_hash}, edgeland replay of its log ${native_hash}"
  native_hash STREQUAL play_hash)
foreach(key edits undos redos inside_solid refused bodies islands_detached islands_left)
  string(JSON ${key} GET "${session}" ${key})
endforeach()
expect("${inside_solid} body centres were inside solid material"
  inside_solid EQUAL 0)
expect("only ${edits} edits (the script makes at least 9)"
  edits GREATER_EQUAL 9)
expect("undos ${undos}, redos ${redos} (want 2 and 1)"
  undos EQUAL 2 AND redos EQUAL 1)
expect("${refused} edits refused"
  refused EQUAL 0)
expect("${islands_detached} islands detached (the ring dug around a piece of rock makes one)"
  islands_detached GREATER_EQUAL 1)
expect("${islands_left} islands left in the landscape after edits settled"
  islands_left EQUAL 0)
expect("no bodies left in the world"
  bodies GREATER 0)
execute_process(COMMAND "${PNG_COLOURS}" "${WORK}/session.script.png" OUTPUT_VARIABLE shot
  RESULT_VARIABLE status)
string(REPLACE " " ";" shot "${shot}")
list(GET shot 2 colours)
expect("the screenshot looks blank: ${colours} colours"
  status EQUAL 0 AND colours GREATER 8)

# 2. Save and load.
run_play(save_load.script 10 saved)
string(JSON loads GET "${saved}" loads)
string(JSON matching GET "${saved}" loads_matching_save)
expect("F9 loaded ${loads} time(s), ${matching} matching the save"
  loads EQUAL 1 AND matching EQUAL 1)
