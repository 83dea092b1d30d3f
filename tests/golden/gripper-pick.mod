MODULE GripperPick
    ! generator: gen-rapid 0.1.0
    ! cell: gripper-pick.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 400.0] yaw: 0.000
    ! tool: tGripper (declared below; collision shapes: housing, finger_a, finger_b, sensor)
    ! wobj: wobjConveyor (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 9
    ! min clearance (mm): 10.3
    ! estimated time (s): 19.73
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 2 (via zone fine)

    PERS tooldata tGripper := [TRUE,[[0.000,0.000,180.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[3.200,[0.000,0.000,80.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjConveyor := [FALSE,TRUE,"",[[700.000,0.000,750.000],[0.707106781,0.000000000,0.000000000,0.707106781]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadPart := [1.200,[0.000,0.000,60.000],[1,0,0,0],0,0,0];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick_rt := [[-300.000,-200.000,30.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[54.000,26.000,10.000,0.000,55.938,142.609],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place_rt := [[900.000,700.000,-20.000],[0.000000000,1.000000000,0.000000000,0.000000000],[1,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[4.000,0.000,0.000,0.000,45.355,6.853],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v1000, fine, tGripper\WObj:=wobjConveyor;
        MoveJ RelTool(pick_rt,0,0,-150.000), v200, fine, tGripper\WObj:=wobjConveyor;
        MoveL pick_rt, v200, fine, tGripper\WObj:=wobjConveyor;
        SetDO doGrip, 1;
        WaitDI diGripClosed, 1;
        GripLoad loadPart;
        MoveL RelTool(pick_rt,0,0,-150.000), v200, fine, tGripper\WObj:=wobjConveyor;
        MoveAbsJ via02_01\NoEOffs, v200, fine, tGripper\WObj:=wobjConveyor;
        MoveJ RelTool(place_rt,0,0,-150.000), v200, fine, tGripper\WObj:=wobjConveyor;
        MoveL place_rt, v200, fine, tGripper\WObj:=wobjConveyor;
        SetDO doGrip, 0;
        WaitDI diGripOpen, 1;
        GripLoad load0;
        MoveL RelTool(place_rt,0,0,-150.000), v200, fine, tGripper\WObj:=wobjConveyor;
        MoveAbsJ via03_01\NoEOffs, v1000, fine, tGripper\WObj:=wobjConveyor;
        MoveAbsJ home2\NoEOffs, v1000, fine, tGripper\WObj:=wobjConveyor;
    ENDPROC
ENDMODULE
