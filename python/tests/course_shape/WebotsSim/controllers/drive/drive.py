# Loads its world, moves to a random start and drives 1.5 m at 18 rad/s, as the course's template does.
from fairis_tools.my_robot import MyRobot

robot = MyRobot()
robot.load_environment('../../worlds/corners.xml')
robot.move_to_start()
start = robot.left_encoder.getValue()
while robot.experiment_supervisor.step(robot.timestep) != -1:
    robot.set_velocities(18, 18)
    if robot.wheel_radius * (robot.left_encoder.getValue() - start) >= 1.5:
        robot.set_velocities(0, 0)
        break
print("start", robot.starting_position)
print("drove 1.5 m by", round(robot.experiment_supervisor.getTime(), 3), "s")
