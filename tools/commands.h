/* tools/commands: one entry point per `scaf` subcommand (one file each). */
#ifndef SCAF_TOOLS_COMMANDS_H
#define SCAF_TOOLS_COMMANDS_H

typedef struct command {
    const char *name;
    const char *summary;               /* one line for `scaf --help` */
    int (*run)(int argc, char **argv); /* argv[0] is the command name */
} command;

/* The table, terminated by a {NULL} entry (tools/main.c). */
extern const command scaf_commands[];

#endif
