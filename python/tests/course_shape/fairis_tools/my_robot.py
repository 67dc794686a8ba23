from fairis_lib.robot_lib.hambot import HamBot


class MyRobot(HamBot):
    def __init__(self):
        HamBot.__init__(self)
