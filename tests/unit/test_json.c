/* test_json.c - the JSON writer: nesting, commas, escapes, numbers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/json.h"
#include "tap.h"

int main(void)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	struct json j;
	json_init(&j, f, 0);
	json_object_begin(&j);
	json_key(&j, "a");
	json_array_begin(&j);
	json_double(&j, 0.1);
	json_double(&j, 1.0 / 3);
	json_double(&j, NAN);
	json_int(&j, -7);
	json_array_end(&j);
	json_key(&j, "s\"q");
	json_string(&j, "line\nbreak\\");
	json_key(&j, "e");
	json_object_begin(&j);
	json_object_end(&j);
	json_key(&j, "b");
	json_bool(&j, 1);
	json_object_end(&j);
	json_end(&j);
	fclose(f);
	const char *want = "{\"a\":[0.1,0.3333333333333333,null,-7],"
			   "\"s\\\"q\":\"line\\nbreak\\\\\",\"e\":{},\"b\":true}\n";
	tap_ok(strcmp(buf, want) == 0, "compact output, shortest round-trip doubles: %s", buf);
	free(buf);
	return tap_done();
}
