# The program that computes the data behind the user manual's figures
# (doc/ISM_reconstruction_3/make_figures.sh runs it, then figures/render_figures.py).
# Included from the top-level CMakeLists.txt, or from figures/CMakeLists.txt for a
# stand-alone build; needs the ISM_reconstruction_3 interface target. Not built by
# default (CGAL headers compile slowly): `cmake --build <build> --target ism_doc_figure_data`.
add_executable(ism_doc_figure_data EXCLUDE_FROM_ALL
               ${CMAKE_CURRENT_LIST_DIR}/figures/make_figure_data.cpp)
target_include_directories(ism_doc_figure_data PRIVATE
                           ${CMAKE_CURRENT_LIST_DIR}/../../test/ISM_reconstruction_3/common)
target_link_libraries(ism_doc_figure_data PRIVATE ISM_reconstruction_3)
