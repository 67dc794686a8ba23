/* Stand-in for Webots' include/controller/c/webots/types.h, which Webots' C++ headers
   include: the device tag type only. */
#ifndef MAZE_MAPPER_STANDIN_TYPES_H
#define MAZE_MAPPER_STANDIN_TYPES_H
typedef unsigned short WbDeviceTag;
#endif
