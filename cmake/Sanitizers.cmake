# AddressSanitizer + UndefinedBehaviorSanitizer for every target when EXACTMESH_SANITIZE is on.
if(EXACTMESH_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
