# A covopt executable whose solver plugins are not where its run path says: `optimize` must
# fail with the message naming the plugin and where it was searched (not crash, not hang).
#   cmake -DCOVOPT=<installed covopt> -DSCRATCH=<dir> -P missing_plugin.cmake
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/bin)
file(COPY ${COVOPT} DESTINATION ${SCRATCH}/bin)
get_filename_component(name ${COVOPT} NAME)
execute_process(COMMAND ${SCRATCH}/bin/${name} optimize RESULT_VARIABLE code
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit ${code}\n${out}${err}")
