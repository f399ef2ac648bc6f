# SPDX-License-Identifier: BSD-3-Clause
# projcurve_defined_api(<out-var> <source>...)
# Lists the public functions (projcurve_*) that the given C sources define,
# recognised by the project's definition style: the return type and the name
# start a line ("projcurve_status projcurve_curve_eval(...").
# Examples and the README example use it to be built only once every public
# function they call has an implementation in the library.
function(projcurve_defined_api out_var)
  set(names "")
  foreach(source ${ARGN})
    file(READ ${source} text)
    string(REGEX MATCHALL "\n[A-Za-z_][A-Za-z0-9_ ]*[ *]projcurve_[a-z0-9_]+\\(" hits "${text}")
    foreach(hit ${hits})
      string(REGEX MATCH "projcurve_[a-z0-9_]+\\($" name "${hit}")
      string(REPLACE "(" "" name "${name}")
      list(APPEND names ${name})
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES names)
  set(${out_var} ${names} PARENT_SCOPE)
endfunction()

# projcurve_missing_api(<out-var> <defined-list-var> <function>...)
# The functions among ARGN that are not in the list named by defined-list-var.
function(projcurve_missing_api out_var defined_var)
  set(missing "")
  foreach(fn ${ARGN})
    if(NOT fn IN_LIST ${defined_var})
      list(APPEND missing ${fn})
    endif()
  endforeach()
  set(${out_var} ${missing} PARENT_SCOPE)
endfunction()

# projcurve_called_api(<out-var> <file>)
# The public functions a file calls (every projcurve_xxx( in it).
function(projcurve_called_api out_var file)
  file(READ ${file} text)
  string(REGEX MATCHALL "projcurve_[a-z0-9_]+\\(" hits "${text}")
  set(names "")
  foreach(hit ${hits})
    string(REPLACE "(" "" name "${hit}")
    list(APPEND names ${name})
  endforeach()
  list(REMOVE_DUPLICATES names)
  set(${out_var} ${names} PARENT_SCOPE)
endfunction()
