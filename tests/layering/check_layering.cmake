cmake_minimum_required(VERSION 3.25)
# The house rules, checked on every ctest run: core <- devices <- widgets <- app, and the
# simulator is one device set among others, known only to itself, the device chooser and the
# simulate workflow. Run as `cmake -DNB_SOURCE_DIR=... -P check_layering.cmake`.
set(violations "")

function(check_folder folder forbidden_regex why)
  file(GLOB_RECURSE files "${NB_SOURCE_DIR}/${folder}/*.h" "${NB_SOURCE_DIR}/${folder}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(line MATCHES "${forbidden_regex}")
        file(RELATIVE_PATH rel "${NB_SOURCE_DIR}" "${f}")
        set(violations "${violations}\n  ${rel}: ${line}  (${why})" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

check_folder(core "[<\"](devices|widgets|app|video)/|<Qt(Widgets|Gui)|<Q(Widget|Application|Image|Painter)>|opencv" "core is Qt Core and Eigen only")
check_folder(devices "[<\"](widgets|app)/|<QtWidgets|<QWidget>" "devices never include views")
check_folder(video "[<\"](widgets|app)/|<QtWidgets|<QWidget>" "video never includes views")
check_folder(widgets "[\"<]app/" "widgets never include the app")

# Who may know the simulator by name.
set(allowed_sim
  "devices/device_spec.cpp"
  "app/cmd_simulate.cpp"
  "app/simulated_run.h"
  "app/simulated_run.cpp")
foreach(folder core devices video widgets app)
  file(GLOB_RECURSE files "${NB_SOURCE_DIR}/${folder}/*.h" "${NB_SOURCE_DIR}/${folder}/*.cpp")
  foreach(f IN LISTS files)
    file(RELATIVE_PATH rel "${NB_SOURCE_DIR}" "${f}")
    if(rel MATCHES "^devices/sim/" OR rel IN_LIST allowed_sim)
      continue()
    endif()
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include.*devices/sim/")
    foreach(line IN LISTS lines)
      set(violations "${violations}\n  ${rel}: ${line}  (only the simulator, the device chooser and simulate know the simulator)")
    endforeach()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "layering violations:${violations}")
endif()
message(STATUS "layering: core <- devices <- widgets <- app holds; the simulator is known only where devices are chosen and in simulate")
