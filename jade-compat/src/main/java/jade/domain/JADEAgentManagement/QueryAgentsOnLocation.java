package jade.domain.JADEAgentManagement;

import jade.core.Location;

/** The AMS action that lists the agents of a container (its answer: a {@code Result} with their AIDs). */
public class QueryAgentsOnLocation implements jade.content.AgentAction {
    private static final long serialVersionUID = 1L;
    private Location location;

    public QueryAgentsOnLocation() {
    }

    public void setLocation(Location l) {
        location = l;
    }

    public Location getLocation() {
        return location;
    }
}
