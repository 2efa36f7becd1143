"""Python client of the swarmplan path-planning service (gRPC API swarmplan.v1).

    from swarmplan_client import Client

    with Client("127.0.0.1:50051") as client:
        record = client.upload_map("warehouse.map")
        result = client.plan(record.id, (2.5, 2.5), (45.5, 27.5), algorithm="astar")
        print(result.path)

The generated stubs are in swarmplan_client._proto.swarmplan.v1 (messages and service stubs
for direct use); Client exposes them as .maps, .jobs and .algorithms.
"""

from ._client import (Algorithm, Client, Job, MapRecord, Parameter, PlanResult,
                      SwarmplanError)
from ._map_files import guess_format

__all__ = ["Algorithm", "Client", "Job", "MapRecord", "Parameter", "PlanResult",
           "SwarmplanError", "guess_format"]
__version__ = "0.1.0"
