MODULE FrameWeld
    ! generator: gen-rapid 0.1.0
    ! cell: frame-weld.yaml
    ! model: irb2600_12_165 (ABB IRB 2600-12/1.65, built into gen-rapid)
    ! urdf: irb2600_12_165.urdf
    ! controller: irb2600_12_165.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! tool: tTorch2600 (declared below; collision shapes: mount, neck, nozzle)
    ! wobj: wobjFrame (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 10
    ! min clearance (mm): 10.3
    ! estimated time (s): 20.92
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 1 (via zone fine)

    PERS tooldata tTorch2600 := [TRUE,[[116.673,0.000,336.673],[0.923879539,0.000000000,0.382683416,0.000000000]],[4.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjFrame := [FALSE,TRUE,"",[[900.000,-400.000,880.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NL1_rt := [[5.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NL2_rt := [[75.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FL1_rt := [[525.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FL2_rt := [[595.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[3.000,7.000,-16.000,89.314,-1.686,-88.818],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FR1_rt := [[525.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FR2_rt := [[595.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NR1_rt := [[5.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NR2_rt := [[75.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ NL1_rt, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ NL2_rt, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ FL1_rt, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ FL2_rt, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ via05_01\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ FR1_rt, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ FR2_rt, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ NR1_rt, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveJ NR2_rt, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ home2\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
    ENDPROC
ENDMODULE
