import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;

/** The names JADE gives: the AMS, the DF, other agents by local name, a GUID, AIDs with spaces trimmed. */
public class Namer extends Agent {
    @Override
    protected void setup() {
        System.out.println("ams " + getAMS().getName() + " df " + getDefaultDF().getName());
        System.out.println("peer " + getAID("peer").getName());
        System.out.println("guid " + AID.createGUID("x", "elsewhere"));
        System.out.println("names " + FIPANames.AMS + " " + FIPANames.DEFAULT_DF + " " + FIPANames.InteractionProtocol.FIPA_REQUEST
                + " " + FIPANames.InteractionProtocol.FIPA_CONTRACT_NET + " " + FIPANames.ContentLanguage.FIPA_SL);
        AID foreign = new AID("bob@other", AID.ISGUID);
        System.out.println("foreign local " + foreign.getLocalName() + " hap " + foreign.getHap());
        AID noAt = new AID("plain", AID.ISGUID);
        System.out.println("no-at local " + noAt.getLocalName());
        System.out.println("hap " + getHap());
        System.out.println("state active " + (getState() == Agent.AP_ACTIVE));
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
