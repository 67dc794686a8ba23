# `from fairis_tools.my_robot import MyRobot` in a controller run by maze_mapper.run where the
# course's own fairis_tools is not on the path: the student's robot, the course's HamBot.
from fairis_lib.robot_lib.hambot import HamBot


class MyRobot(HamBot):
    """The student's robot class: HamBot as it comes."""
