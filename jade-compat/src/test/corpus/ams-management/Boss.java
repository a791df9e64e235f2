import jade.content.ContentElement;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Result;
import jade.core.AID;
import jade.core.Agent;
import jade.core.ContainerID;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.AMSService;
import jade.domain.FIPAAgentManagement.AMSAgentDescription;
import jade.domain.FIPAAgentManagement.SearchConstraints;
import jade.domain.FIPANames;
import jade.domain.FIPAService;
import jade.domain.JADEAgentManagement.CreateAgent;
import jade.domain.JADEAgentManagement.JADEManagementOntology;
import jade.domain.JADEAgentManagement.KillAgent;
import jade.domain.JADEAgentManagement.QueryAgentsOnLocation;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.util.leap.Iterator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Manages the platform through the AMS, as JADE code does: creates a worker with a CreateAgent
 * request, lists the agents with AMSService.search, asks which agents live on the main
 * container (QueryAgentsOnLocation), kills the worker with a KillAgent request.
 */
public class Boss extends Agent {
    @Override
    protected void setup() {
        getContentManager().registerLanguage(new SLCodec(), FIPANames.ContentLanguage.FIPA_SL);
        getContentManager().registerOntology(JADEManagementOntology.getInstance());
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    manage();
                } catch (Exception e) {
                    System.out.println("boss failed: " + e);
                }
                myAgent.doDelete();
            }
        });
    }

    private ACLMessage ask(jade.content.AgentAction what) throws Exception {
        ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
        req.addReceiver(getAMS());
        req.setLanguage(FIPANames.ContentLanguage.FIPA_SL);
        req.setOntology(JADEManagementOntology.NAME);
        req.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        getContentManager().fillContent(req, new Action(getAMS(), what));
        ACLMessage reply = FIPAService.doFipaRequestClient(this, req, 20000);
        System.out.println(what.getClass().getSimpleName() + ": " + ACLMessage.getPerformative(reply.getPerformative()));
        return reply;
    }

    private void manage() throws Exception {
        CreateAgent ca = new CreateAgent();
        ca.setAgentName("worker1");
        ca.setClassName("Worker");
        ca.setContainer(new ContainerID("Main-Container", null));
        ca.addArguments(getLocalName());
        ask(ca);
        System.out.println("boss heard: " + blockingReceive(MessageTemplate.MatchContent("hello from worker1")).getContent());
        getContainerController().createNewAgent("worker2", "Worker", new Object[] {getLocalName()}).start();
        System.out.println("boss heard: " + blockingReceive(MessageTemplate.MatchContent("hello from worker2")).getContent());

        System.out.println("agents found with the default constraints: " + AMSService.search(this, new AMSAgentDescription()).length);
        SearchConstraints all = new SearchConstraints();
        all.setMaxResults(-1L);
        System.out.println("agents: " + names(AMSService.search(this, new AMSAgentDescription(), all)));
        AMSAgentDescription byName = new AMSAgentDescription();
        byName.setName(new AID("worker1", AID.ISLOCALNAME));
        AMSAgentDescription[] found = AMSService.search(this, byName, all);
        System.out.println("worker1 found: " + found.length + " " + found[0].getName().getLocalName() + " " + found[0].getState());

        QueryAgentsOnLocation q = new QueryAgentsOnLocation();
        q.setLocation(new ContainerID("Main-Container", null));
        ACLMessage r = ask(q);
        ContentElement ce = getContentManager().extractContent(r);
        List<String> onMain = new ArrayList<>();
        for (Iterator it = ((Result) ce).getItems().iterator(); it.hasNext(); ) {
            onMain.add(((AID) it.next()).getLocalName());
        }
        Collections.sort(onMain);
        System.out.println("on the main container: " + onMain);

        KillAgent ka = new KillAgent();
        ka.setAgent(new AID("worker1", AID.ISLOCALNAME));
        ask(ka);
        System.out.println("boss heard: " + blockingReceive(MessageTemplate.MatchContent("bye from worker1")).getContent());
        System.out.println("worker1 found after the kill: " + AMSService.search(this, byName, all).length);

        KillAgent nobody = new KillAgent();
        nobody.setAgent(new AID("nobody", AID.ISLOCALNAME));
        try {
            ask(nobody);
        } catch (jade.domain.FIPAException e) {
            System.out.println("killing nobody: " + e.getClass().getSimpleName() + " "
                    + ACLMessage.getPerformative(e.getACLMessage().getPerformative()));
        }
        getContainerController().getAgent("worker2").kill();
        System.out.println("boss heard: " + blockingReceive(MessageTemplate.MatchContent("bye from worker2")).getContent());
    }

    private static List<String> names(AMSAgentDescription[] ds) {
        List<String> l = new ArrayList<>();
        for (AMSAgentDescription d : ds) {
            l.add(d.getName().getLocalName() + "/" + d.getState());
        }
        Collections.sort(l);
        return l;
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
