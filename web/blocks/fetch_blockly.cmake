# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DNPM=... -DDIR=... -P fetch_blockly.cmake: npm install in DIR with
# bounded waits; a failure is a warning, never a failed build.
if(NOT NPM)
    message(WARNING "npm is not installed: the blocks page has no Blockly and says so")
    return()
endif()
execute_process(COMMAND ${NPM} install --no-audit --no-fund --no-save --fetch-timeout=30000 --fetch-retries=1
    WORKING_DIRECTORY ${DIR} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT result EQUAL 0)
    message(WARNING "npm could not install Blockly into ${DIR} (${result}): the blocks page says Blockly is missing. "
                    "Build again with the npm registry reachable.\n${err}")
elseif(NOT EXISTS ${DIR}/node_modules/blockly/LICENSE)
    message(WARNING "npm installed no Blockly licence into ${DIR}/node_modules/blockly")
endif()
