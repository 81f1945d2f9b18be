/* servicebot's test driver for rcl's parameter file reader: ACCEPT or REFUSE (with rcl's own
 * error text) per file given; PRINT=1 in the environment also prints what rcl read. */
#include <stdlib.h>
#include <stdio.h>
#include "rcl_yaml_param_parser/parser.h"
#include "rcutils/error_handling.h"
int main(int argc, char **argv) {
  rcutils_allocator_t a = rcutils_get_default_allocator();
  int bad = 0;
  for (int i = 1; i < argc; i++) {
    rcl_params_t *p = rcl_yaml_node_struct_init(a);
    if (rcl_parse_yaml_file(argv[i], p)) {
      printf("ACCEPT %s\n", argv[i]);
      if (getenv("PRINT")) rcl_yaml_node_struct_print(p);
    } else {
      printf("REFUSE %s: %s\n", argv[i], rcutils_get_error_string().str);
      rcutils_reset_error(); bad = 1;
    }
    rcl_yaml_node_struct_fini(p);
  }
  return bad;
}
