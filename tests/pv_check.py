"""pvpython pv_check.py VIEW.xdmf FRAME.tsv PNG: ParaView's XDMF reader on a wetgran-xdmf file.
Prints 'ok'/'FAIL' lines: the number of time steps, the points, the arrays, the last frame's
positions and velocities against wetgran-frame's table (FRAME.tsv), and a rendered PNG."""
import sys
from paraview.simple import XDMFReader, CreateRenderView, Show, ResetCamera, SaveScreenshot
from paraview import servermanager

xdmf, table, png, nframes = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
rows = [l.split('\t') for l in open(table) if not l.startswith('#')]
head, rows = rows[0], rows[1:]
dim = sum(1 for h in head if h in ('x', 'y', 'z'))
reader = XDMFReader(FileNames=[xdmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
print(("ok    " if len(times) == nframes else "FAIL  ") + f"ParaView sees {len(times)} time steps ({nframes} snapshots)")
reader.UpdatePipeline(times[-1])
grid = servermanager.Fetch(reader)
if grid.IsA("vtkMultiBlockDataSet"):
    grid = grid.GetBlock(0)
n = grid.GetNumberOfPoints()
print(("ok    " if n == len(rows) else "FAIL  ") + f"{n} points in the last step ({len(rows)} grains)")
pd = grid.GetPointData()
names = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))
print(("ok    " if names == ['bridges', 'diameter', 'velocity'] else "FAIL  ") + f"arrays {names}")
worst = 0.0
vel = pd.GetArray('velocity')
for i, r in enumerate(rows):
    p = grid.GetPoint(i)
    v = vel.GetTuple(i)
    want_p = [float(x) for x in r[1:1 + dim]] + [0.0] * (3 - dim)
    want_v = [float(x) for x in r[1 + dim:1 + 2 * dim]] + [0.0] * (3 - dim)
    worst = max(worst, max(abs(a - b) / (1 + abs(b)) for a, b in zip(list(p) + list(v), want_p + want_v)))
print(("ok    " if worst < 1e-8 else "FAIL  ") + f"positions and velocities of the last step as wetgran-frame prints them (worst {worst:.1e})")
view = CreateRenderView()
view.ViewSize = [320, 240]
Show(reader, view)
view.ViewTime = times[-1]
ResetCamera(view)
SaveScreenshot(png, view)
