# Copies a test driver's SETUP into its folder: `setup` is '|'-separated FROM=TO pairs, FROM a path,
# TO relative to `work` (its folders are made). include() it, then call copy_setup().
function(copy_setup work setup)
  string(REPLACE "|" ";" setup "${setup}")
  foreach(pair ${setup})
    string(REPLACE "=" ";" pair "${pair}")
    list(GET pair 0 from)
    list(GET pair 1 to)
    get_filename_component(folder ${work}/${to} DIRECTORY)
    file(MAKE_DIRECTORY ${folder})
    file(COPY_FILE ${from} ${work}/${to})
  endforeach()
endfunction()
