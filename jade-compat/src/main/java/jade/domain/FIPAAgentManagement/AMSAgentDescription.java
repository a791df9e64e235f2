package jade.domain.FIPAAgentManagement;

import jade.core.AID;

/** What the AMS knows of an agent: its name, ownership and state ({@link #ACTIVE}, ...). */
public class AMSAgentDescription implements jade.content.Concept {
    private static final long serialVersionUID = 1L;
    public static final String INITIATED = "initiated";
    public static final String ACTIVE = "active";
    public static final String SUSPENDED = "suspended";
    public static final String WAITING = "waiting";
    public static final String TRANSIT = "transit";
    public static final String LATENT = "latent";

    private AID name;
    private String ownership;
    private String state;

    public AMSAgentDescription() {
    }

    public void setName(AID n) {
        name = n;
    }

    public AID getName() {
        return name;
    }

    public void setOwnership(String o) {
        ownership = o;
    }

    public String getOwnership() {
        return ownership;
    }

    public void setState(String s) {
        state = s;
    }

    public String getState() {
        return state;
    }
}
