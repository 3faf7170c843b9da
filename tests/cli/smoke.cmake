# Basic contract: help, version, usage errors.
throng_cli_test(cli.help EXIT 0 STDOUT "Usage: throng <command>" ARGS --help)
throng_cli_test(cli.bvh_info_help EXIT 0 STDOUT "Usage: throng bvh info" ARGS bvh info --help)
throng_cli_test(cli.bvh_bake_help EXIT 0 STDOUT "Usage: throng bvh bake" ARGS bvh bake --help)
throng_cli_test(cli.unknown_command EXIT 2 STDERR "unknown command 'frobnicate'" ARGS frobnicate)
throng_cli_test(cli.bake_needs_json EXIT 2 STDERR "needs --json" ARGS bvh bake ${THRONG_ASSET_DIR}/walk.bvh)
throng_cli_test(cli.missing_file EXIT 2 STDERR "no-such\\.bvh: error: cannot open BVH file: no such file"
                ARGS bvh info ${CMAKE_CURRENT_BINARY_DIR}/no-such.bvh)
throng_cli_test(cli.bake_missing_file_writes_nothing EXIT 2 STDERR "cannot open BVH file"
                NO_FILE ${CMAKE_CURRENT_BINARY_DIR}/never.json
                ARGS bvh bake ${CMAKE_CURRENT_BINARY_DIR}/no-such.bvh --json ${CMAKE_CURRENT_BINARY_DIR}/never.json)
