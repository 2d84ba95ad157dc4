# The three.js example's packages, as its lockfile pins them, installed into
# SITE with `npm ci` (cmake -DNPM=... -DEXAMPLE=... -DSITE=... -P).
file(MAKE_DIRECTORY ${SITE})
file(COPY ${EXAMPLE}/package.json ${EXAMPLE}/package-lock.json DESTINATION ${SITE})
execute_process(
  COMMAND ${NPM} ci --no-audit --no-fund --ignore-scripts
  WORKING_DIRECTORY ${SITE}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "npm ci in ${SITE} failed (${status}): the three.js example needs the npm registry")
endif()
