/* commands.h: the subcommands of the hearth executable. Each returns the
 * process exit status: 0 ok, 1 a scene or run error, 2 bad usage, 3 guard stop. */
#ifndef HEARTH_APP_COMMANDS_H
#define HEARTH_APP_COMMANDS_H

int cmd_demo(int argc, char **argv);
int cmd_plugins(int argc, char **argv);
int cmd_plugin_check(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_run(int argc, char **argv);
int cmd_repl(int argc, char **argv);

/// Parse a whole positive integer option value; prints a usage error and returns -1 when bad.
long app_parse_int(const char *cmd, const char *flag, const char *text, long min, long max);
#endif
