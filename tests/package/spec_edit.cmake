# Part of consume.cmake (its run(), WORK_DIR, PYTHON, GENERATOR): an app of
# the installed package whose spec is edited is built again, with the new
# algebra, by one build. (Under Ninja it took two until gaphys_add_algebra
# named the generated headers: the first build regenerated them after Ninja
# had found the app's object up to date, and the app kept the old metric.)
set(edit "${WORK_DIR}/spec_edit")
file(WRITE "${edit}/CMakeLists.txt"
     "cmake_minimum_required(VERSION 3.25)\n"
     "project(spec_edit CXX)\n"
     "set(CMAKE_CXX_STANDARD 17)\n"
     "find_package(gaphys REQUIRED)\n"
     "gaphys_add_algebra(TARGET plane SPEC \"\${CMAKE_CURRENT_SOURCE_DIR}/plane.ga\")\n"
     "add_executable(square main.cpp)\n"
     "target_link_libraries(square PRIVATE plane)\n")
file(WRITE "${edit}/main.cpp"
     "#include <cstdio>\n"
     "#include <plane/plane.hpp>\n"
     "int main() { std::printf(\"%g\", plane::scp(plane::vector{1, 0}, plane::vector{1, 0})); }\n")
function(spec_with_metric value)
  file(WRITE "${edit}/plane.ga"
       "algebra plane\nbasis e1 e2\nmetric e1.e1 = ${value}, e2.e2 = 1\nscalar double\n"
       "type vector = e1, e2\nfunction scp(vector, vector)\n")
endfunction()
function(expect_square value)
  run("${CMAKE_COMMAND}" --build "${edit}/build")
  execute_process(COMMAND "${edit}/build/square" OUTPUT_VARIABLE printed RESULT_VARIABLE failed)
  if(failed OR NOT printed STREQUAL "${value}")
    message(FATAL_ERROR "after one build with e1.e1 = ${value} in plane.ga, the app printed "
                        "'${printed}' (exit ${failed}), not ${value}")
  endif()
endfunction()
spec_with_metric(2)
run("${CMAKE_COMMAND}" -S "${edit}" -B "${edit}/build" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/install" "-DPython3_EXECUTABLE=${PYTHON}")
expect_square(2)
spec_with_metric(3)
expect_square(3)
