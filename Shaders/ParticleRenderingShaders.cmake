# particlerendering_embed_shaders(<folder> <sources-var> <headers-var>)
#
# Embeds every Shaders/<folder>/*.glsl in the module that calls it (vtk_encode_string) and
# generates a table that registers them with vtkParticleShaders when the module's library loads
# (Representations/Core/vtkParticleShaderTable.cxx.in). The folder is the module's name: a module
# owns its GLSL as it owns its classes, and Scripts/check_layering.py checks that a shader
# includes only its own folder's and the core's. The generated sources and private headers are
# returned in <sources-var> and <headers-var> for vtk_module_add_module(SOURCES, PRIVATE_HEADERS).
function (particlerendering_embed_shaders folder sources_var headers_var)
  file(GLOB shader_files CONFIGURE_DEPENDS "${PARTICLERENDERING_SHADER_DIR}/${folder}/*.glsl")
  set(sources)
  set(headers)
  set(PR_SHADER_FOLDER "${folder}")
  set(PR_SHADER_INCLUDES "")
  set(PR_SHADER_TABLE "")
  foreach (shader IN LISTS shader_files)
    get_filename_component(shader_name "${shader}" NAME_WE)
    vtk_encode_string(
      INPUT         "${shader}"
      NAME          "vtkParticleGLSL_${shader_name}"
      HEADER_OUTPUT shader_header
      SOURCE_OUTPUT shader_source)
    list(APPEND sources "${shader_source}")
    list(APPEND headers "${shader_header}")
    string(APPEND PR_SHADER_INCLUDES "#include \"vtkParticleGLSL_${shader_name}.h\"\n")
    string(APPEND PR_SHADER_TABLE "  { \"${shader_name}\", vtkParticleGLSL_${shader_name} },\n")
  endforeach ()
  set(table "${CMAKE_CURRENT_BINARY_DIR}/vtkParticleShaderTable${folder}.cxx")
  configure_file("${PARTICLERENDERING_SHADER_TABLE_TEMPLATE}" "${table}" @ONLY)
  list(APPEND sources "${table}")
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
